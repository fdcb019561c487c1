namespace Machina.Simulation;

/// <summary>How a <see cref="VirtualKukaController"/> writes its acknowledgements to the socket (to test how the host reads them).</summary>
public enum AcknowledgementWrites
{
    /// <summary>One write per acknowledgement.</summary>
    Whole,

    /// <summary>Each acknowledgement in two writes, cut inside the element.</summary>
    Split,

    /// <summary>Two acknowledgements in one write whenever a second action is waiting to run.</summary>
    Joined,
}

/// <summary>Settings of a <see cref="VirtualKukaController"/>. Every property has a usable default.</summary>
public sealed record VirtualKukaControllerOptions : VirtualControllerOptions
{
    /// <summary>A KR 6 R900 sixx at (0, -90, 90, 0, 90, 0): upper arm up, forearm forward, tool pointing down.</summary>
    public VirtualKukaControllerOptions()
    {
        Model = RobotModels.Get("KR 6 R900 sixx");
        InitialJoints = new Joints(0, -90, 90, 0, 90, 0);
    }

    /// <summary>Time between two pose reports on the monitor port until the host asks for another. Default 20 ms (50 Hz).</summary>
    public TimeSpan MonitorPeriod { get; init; } = TimeSpan.FromMilliseconds(20);

    /// <summary>
    /// Driver version sent in the state (<c>VR</c>): by default 2.1, the shipped KRL driver. An older 2.x runs the shipped driver
    /// reporting that version, as an installed older driver would greet a host (2.0 ran no CIRC).
    /// </summary>
    public Version DriverVersion { get; init; } = ShippedDriverVersion;

    /// <summary>The version of the driver in drivers/kuka (its <c>S/@VR</c>).</summary>
    internal static Version ShippedDriverVersion { get; } = new(2, 1);

    /// <summary>How acknowledgements are written. Default: one write each.</summary>
    public AcknowledgementWrites AcknowledgementWrites { get; init; } = AcknowledgementWrites.Whole;

    /// <summary>
    /// True, the only value: the controller runs Machina's KRL driver and monitor (drivers/kuka, unchanged) on a KRL interpreter
    /// with EthernetKRL, the monitor in the submit interpreter, as a KR C4 would. False is refused (the C# imitation of the
    /// driver was removed); kept for source compatibility.
    /// </summary>
    public bool RunsKrl { get; init; } = true;

    /// <summary>Where the robot starts without a model: (455, 0, 935) with the tool pointing down.</summary>
    internal static Pose DefaultStart => new(new Vector(455, 0, 935), Rotation.FlippedAroundY);

    internal override void Validate()
    {
        base.Validate();
        if (MonitorPeriod <= TimeSpan.Zero)
        {
            throw new ArgumentException("MonitorPeriod must be positive.", nameof(MonitorPeriod));
        }
        ArgumentNullException.ThrowIfNull(DriverVersion);
        if (!RunsKrl)
        {
            throw new ArgumentException("The virtual KUKA runs only Machina's KRL driver (drivers/kuka) on its KRL interpreter; the C# imitation of the driver (RunsKrl = false) was removed.", nameof(RunsKrl));
        }
        if (DriverVersion.Major != 2 || DriverVersion > ShippedDriverVersion)
        {
            throw new ArgumentException($"The virtual KUKA runs the shipped KRL driver, version {ShippedDriverVersion}, or an older 2.x as it greeted a host, not {DriverVersion}.", nameof(DriverVersion));
        }
    }
}
