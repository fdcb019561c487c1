namespace Machina.Simulation;

/// <summary>Settings of a <see cref="VirtualAbbController"/>. Every property has a usable default.</summary>
public sealed record VirtualAbbControllerOptions
{
    /// <summary>Joint angles (degrees) at start. Default: the ABB home position (0, 0, 0, 0, 90, 0).</summary>
    public Joints InitialJoints { get; init; } = new(0, 0, 0, 0, 90, 0);

    /// <summary>Flange position (mm) at start. Default: (374, 0, 630), an IRB 120 at home.</summary>
    public Vector InitialPosition { get; init; } = new(374, 0, 630);

    /// <summary>Flange orientation at start. Default: tool pointing down (quaternion 0, 0, 1, 0).</summary>
    public Rotation InitialRotation { get; init; } = Rotation.FromQuaternion(0, 0, 1, 0);

    /// <summary>External axes at start. Default: none (reported as 9E9).</summary>
    public ExternalAxes InitialExternalAxes { get; init; } = ExternalAxes.None;

    /// <summary>How much faster than real time motions and waits run (10 = ten times faster). Default 1.</summary>
    public double SpeedFactor { get; init; } = 1;

    /// <summary>When true every instruction completes at once (for tests and benchmarks). Default false.</summary>
    public bool InstantExecution { get; init; }

    /// <summary>How many received requests wait for execution before the controller stops reading the socket. Default 1000, like the RAPID driver.</summary>
    public int BufferCapacity { get; init; } = 1000;

    /// <summary>Time between two state reports on the monitor port. Default 20 ms (50 Hz).</summary>
    public TimeSpan MonitorPeriod { get; init; } = TimeSpan.FromMilliseconds(20);

    /// <summary>How many received requests are kept in <see cref="VirtualAbbController.ReceivedRequests"/> (oldest dropped). 0 keeps none. Default 10 000.</summary>
    public int RequestLogCapacity { get; init; } = 10_000;

    /// <summary>Driver version sent in the handshake. Default 1.6.0, the version of Machina's RAPID driver; below 1.6 the handshake has no progress (<c>$25</c>).</summary>
    public Version DriverVersion { get; init; } = new(1, 6, 0);

    /// <summary>Clock used for motion timing and monitor reports. Default: the system clock.</summary>
    public TimeProvider TimeProvider { get; init; } = TimeProvider.System;

    /// <summary>Optional robot model linking joints and pose; null keeps them independent.</summary>
    public IVirtualKinematics? Kinematics { get; init; }

    internal void Validate()
    {
        if (!(SpeedFactor > 0) || !double.IsFinite(SpeedFactor))
        {
            throw new ArgumentException("SpeedFactor must be a positive number.", nameof(SpeedFactor));
        }
        if (BufferCapacity < 1)
        {
            throw new ArgumentException("BufferCapacity must be at least 1.", nameof(BufferCapacity));
        }
        if (MonitorPeriod <= TimeSpan.Zero)
        {
            throw new ArgumentException("MonitorPeriod must be positive.", nameof(MonitorPeriod));
        }
        if (RequestLogCapacity < 0)
        {
            throw new ArgumentException("RequestLogCapacity cannot be negative.", nameof(RequestLogCapacity));
        }
        ArgumentNullException.ThrowIfNull(TimeProvider);
        ArgumentNullException.ThrowIfNull(DriverVersion);
        if (!InitialPosition.IsFinite || !InitialJoints.IsFinite)
        {
            throw new ArgumentException("The initial position and joints must be finite numbers.");
        }
    }
}
