using Machina.Simulation.Twin;

namespace Machina.Simulation.Rapid;

/// <summary>Settings of a RAPID twin controller.</summary>
internal sealed record RapidTwinOptions : TwinOptions
{
    /// <summary>Settings with the virtual ABB's arm: an IRB 120 at ABB's calibration position with the wrist bent down.</summary>
    public RapidTwinOptions()
        : base(RobotModels.Get("IRB 120"), new Joints(0, 0, 0, 0, 90, 0))
    {
    }

    /// <summary>The IO configuration: signal names with their type (signaldo, signaldi, signalao, signalai).</summary>
    public IReadOnlyList<(string Name, string Type)> Signals { get; init; } = [];

    /// <summary>The TCP acceleration (m/s²) motion time assumes when the program sets no WorldAccLim.</summary>
    public double Acceleration { get; init; } = 5;

    /// <summary>Where a hosting controller watches and disturbs the program's sockets (faults, inspection); null: direct sockets.</summary>
    public IRapidSocketSeam? Seam { get; init; }

    /// <summary>The address the controller serves on, as GetSysInfo(\LanIp) reports it (default 127.0.0.1).</summary>
    public string LanIp { get; init; } = "127.0.0.1";

    /// <summary>
    /// The RETRYs an error handler may make before the next one raises ERR_EXCRTYMAX, an error inside the handler that stops the task
    /// (the system parameter General RAPID "No Of Retry", 4 by default on a controller); 0: no limit.
    /// </summary>
    public int MaxRetries { get; init; } = 4;

    /// <summary>The directory that stands for the controller's HOME: (TEMP: and RAMDISK: are folders in it); null: a new temporary directory.</summary>
    public string? HomeDirectory { get; init; }
}
