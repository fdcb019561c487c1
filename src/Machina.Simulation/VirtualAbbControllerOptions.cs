namespace Machina.Simulation;

/// <summary>Settings of a <see cref="VirtualAbbController"/>. Every property has a usable default.</summary>
public sealed record VirtualAbbControllerOptions : VirtualControllerOptions
{
    /// <summary>An IRB 120 at the ABB home position (0, 0, 0, 0, 90, 0): flange at [302, 0, 558], tool pointing down.</summary>
    public VirtualAbbControllerOptions()
    {
        Model = RobotModels.Get("IRB 120");
        InitialJoints = new Joints(0, 0, 0, 0, 90, 0);
    }

    /// <summary>External axes at start. Default: none (reported as 9E9).</summary>
    public ExternalAxes InitialExternalAxes { get; init; } = ExternalAxes.None;

    /// <summary>Time between two state reports on the monitor port. Default 20 ms (50 Hz).</summary>
    public TimeSpan MonitorPeriod { get; init; } = TimeSpan.FromMilliseconds(20);

    /// <summary>Driver version sent in the handshake. Default 1.6.0, the version of Machina's RAPID driver; below 1.6 the handshake has no progress (<c>$25</c>).</summary>
    public Version DriverVersion { get; init; } = new(1, 6, 0);

    /// <summary>
    /// True (default): the controller runs Machina's RAPID driver and monitor (drivers/abb) on a RAPID interpreter, in two tasks, as
    /// an IRC5 would, on <c>Model</c> (an IRB 1600-8/1.45 when null); faults and inspection act on the driver task's socket. False: Machina's
    /// driver is imitated in C# (to be removed).
    /// </summary>
    public bool RunsRapid { get; init; } = true;

    /// <summary>Where the robot starts without a model: (374, 0, 630), tool pointing down (quaternion 0, 0, 1, 0).</summary>
    internal static Pose DefaultStart => new(new Vector(374, 0, 630), Rotation.FromQuaternion(0, 0, 1, 0));

    internal override void Validate()
    {
        base.Validate();
        if (MonitorPeriod <= TimeSpan.Zero)
        {
            throw new ArgumentException("MonitorPeriod must be positive.", nameof(MonitorPeriod));
        }
        ArgumentNullException.ThrowIfNull(DriverVersion);
    }
}
