using Machina.Simulation.Twin;

namespace Machina.Simulation.Rapid;

/// <summary>Settings of a RAPID twin controller.</summary>
internal sealed class RapidTwinOptions
{
    /// <summary>The arm model (default IRB 120, as the virtual ABB).</summary>
    public RobotModel Model { get; init; } = RobotModels.Get("IRB 120");

    /// <summary>The joints (degrees) the arm starts at: ABB's calibration position with the wrist bent down.</summary>
    public Joints StartJoints { get; init; } = new(0, 0, 0, 0, 90, 0);

    /// <summary>The time source for real-time motion and waits.</summary>
    public TimeProvider Time { get; init; } = TimeProvider.System;

    /// <summary>True: motion and waits take their time on <see cref="Time"/>; false: they return at once (program time still adds up).</summary>
    public bool RealTime { get; init; }

    /// <summary>The IO configuration: signal names with their type (signaldo, signaldi, signalao, signalai).</summary>
    public IReadOnlyList<(string Name, string Type)> Signals { get; init; } = [];

    /// <summary>The TCP acceleration (m/s²) motion time assumes when the program sets no WorldAccLim.</summary>
    public double Acceleration { get; init; } = 5;

    /// <summary>Where a hosting controller watches and disturbs the program's sockets (faults, inspection); null: direct sockets.</summary>
    public IRapidSocketSeam? Seam { get; init; }

    /// <summary>The address the controller serves on, as GetSysInfo(\LanIp) reports it (default 127.0.0.1).</summary>
    public string LanIp { get; init; } = "127.0.0.1";

    /// <summary>
    /// The RETRYs an error handler may make before the error becomes ERR_EXCRTYMAX, raised to the caller (the system parameter
    /// General RAPID "No Of Retry", 4 by default on a controller); 0: no limit.
    /// </summary>
    public int MaxRetries { get; init; } = 4;

    /// <summary>The directory that stands for the controller's HOME: (TEMP: and RAMDISK: are folders in it); null: a new temporary directory.</summary>
    public string? HomeDirectory { get; init; }

    /// <summary>The interpreter's budgets (nesting, expression size, calls, steps, arrays, module size).</summary>
    public TwinLimits Limits { get; init; } = TwinLimits.Default;
}
