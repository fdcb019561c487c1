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

    /// <summary>External axes at start. The twin's arm has none: only the default (none, reported as 9E9) is accepted.</summary>
    public ExternalAxes InitialExternalAxes { get; init; } = ExternalAxes.None;

    /// <summary>Time between two state reports on the monitor port. Default 20 ms (50 Hz).</summary>
    public TimeSpan MonitorPeriod { get; init; } = TimeSpan.FromMilliseconds(20);

    /// <summary>
    /// Version of the RAPID driver the controller runs. Default 1.7.0, the shipped driver; an older 1.x runs it as that version
    /// spoke: its version in the handshake and, below 1.6, no progress report (<c>$25</c>). Newer versions are refused.
    /// </summary>
    public Version DriverVersion { get; init; } = ShippedDriverVersion;

    /// <summary>
    /// The folder that the controller's mass memory is: RAPID's <c>HOME:</c> (<c>TEMP:</c> and <c>RAMDISK:</c> are folders in it) and
    /// Robot Web Services' <c>/fileservice/$HOME</c>; null: a new temporary folder (<c>machina sim abb --home DIR</c>).
    /// </summary>
    internal string? HomeDirectory { get; init; }

    /// <summary>The version of the driver in drivers/abb (its DRIVER_VERSION constants).</summary>
    internal static Version ShippedDriverVersion { get; } = new(1, 7, 0);

    /// <summary>
    /// Always true: the controller runs Machina's RAPID driver and monitor (drivers/abb) on a RAPID interpreter, in two tasks, as
    /// an IRC5 would, on <c>Model</c> (an IRB 1600-8/1.45 when null); faults and inspection act on the driver task's socket. False
    /// is refused: the C# imitation of the driver it chose was removed.
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
        if (!RunsRapid)
        {
            throw new ArgumentException("The virtual ABB always runs the RAPID driver (its C# imitation was removed): leave RunsRapid true.", nameof(RunsRapid));
        }
        if (InitialExternalAxes != ExternalAxes.None)
        {
            throw new ArgumentException("The virtual ABB's arm has no external axes (the RAPID twin reports 9E9): leave InitialExternalAxes at none.", nameof(InitialExternalAxes));
        }
        if (DriverVersion.Major != 1 || DriverVersion > ShippedDriverVersion)
        {
            throw new ArgumentException($"The virtual ABB runs Machina's RAPID driver {ShippedDriverVersion} or an older 1.x as it spoke, not {DriverVersion}.", nameof(DriverVersion));
        }
    }
}
