using System.Globalization;
using System.Net.Sockets;
using Machina.Simulation.Rapid;
using Machina.Simulation.Twin;

namespace Machina.Simulation;

public sealed partial class VirtualAbbController
{
    /// <summary>The RAPID controller that runs Machina's driver and monitor modules, once started; else null.</summary>
    internal RapidTwinController? Twin { get; private set; }

    /// <summary>
    /// Loads drivers/abb as <c>machina drivers abb</c> writes them (driver in T_ROB1 on <see cref="Port"/>, monitor in
    /// T_MACHINA_MONITOR on port + 1) and starts both tasks; their SocketListen takes the ports bound here.
    /// </summary>
    private void StartTwin(TcpListener driver, TcpListener monitor)
    {
        var twin = new RapidTwinController(new RapidTwinOptions
        {
            Model = Model ?? RobotModels.Get(FallbackModel),
            Seam = this,
            Signals = Signals,
            StartJoints = TwinStartJoints(),
            // Robot time runs SpeedFactor times faster than the controller's clock (the UR twin's scaled clock, brand-neutral).
            Time = TwinScaledTime.Of(Clock, _options.SpeedFactor),
            RealTime = !_options.InstantExecution,
            HomeDirectory = _options.HomeDirectory,
        });
        // The shipped files with their placeholders filled, as an installer writes them (the host's AbbDriverModules does the same).
        string interval = Math.Max(0.004, _options.MonitorPeriod.TotalSeconds).ToString("0.###", CultureInfo.InvariantCulture);
        foreach ((string file, string task, int port) in new[] { ("machina_abb_driver.mod", RapidTwinController.MotionTask, Port), ("machina_abb_monitor.mod", MonitorTask, MonitorPort) })
        {
            string text = DriverFiles.Fill(DriverFiles.Read(file),
                ("HOSTNAME", "127.0.0.1"), ("PORT", port.ToString(CultureInfo.InvariantCulture)), ("MONITOR_INTERVAL", interval));
            if (task == RapidTwinController.MotionTask)
            {
                text = AsDriverVersion(text, _options.DriverVersion);
            }
            _modules.Add((task, file, text));
            twin.Task(task).Load([(file, text)]);
        }
        twin.Pendant.Logged += line =>
        {
            if (line.StartsWith("Execution error", StringComparison.Ordinal) || IsEventError(line))
            {
                RecordError(line);
            }
            else
            {
                Pendant(line);
            }
        };
        twin.Reserve(driver);
        twin.Reserve(monitor);
        Twin = twin;
        twin.StartTasks();
    }

    /// <summary>
    /// True for the event-log form of an error that stopped a task, <c>50050 Position outside reach: … (line N, task T_ROB1)</c>:
    /// an error, as "Execution error" is (listed in <see cref="VirtualController{TState}.Errors"/> as UR and KUKA list theirs).
    /// </summary>
    private static bool IsEventError(string line)
    {
        int digits = 0;
        while (digits < line.Length && char.IsAsciiDigit(line[digits]))
        {
            digits++;
        }
        return digits >= 4 && digits < line.Length && line[digits] == ' '
            && line.EndsWith(')') && line.Contains(", task ", StringComparison.Ordinal) && line.Contains("(line ", StringComparison.Ordinal);
    }

    /// <summary>
    /// The driver module as <paramref name="version"/> had it: its version constants, and below 1.6 without the progress report
    /// (<c>$25</c>) in its handshake, which came in 1.6. The shipped version leaves the module as it is.
    /// </summary>
    private static string AsDriverVersion(string module, Version version)
    {
        if (version == VirtualAbbControllerOptions.ShippedDriverVersion)
        {
            return module;
        }
        var lines = module.Split('\n').Where(line => version >= new Version(1, 6) || !line.Contains("\"$25 \"", StringComparison.Ordinal));
        return string.Join('\n', lines)
            .Replace("DRIVER_VERSION_MAJOR := \"1\"", $"DRIVER_VERSION_MAJOR := \"{version.Major}\"", StringComparison.Ordinal)
            .Replace("DRIVER_VERSION_MINOR := \"7\"", $"DRIVER_VERSION_MINOR := \"{version.Minor}\"", StringComparison.Ordinal)
            .Replace("DRIVER_VERSION_PATCH := \"0\"", $"DRIVER_VERSION_PATCH := \"{Math.Max(0, version.Build)}\"", StringComparison.Ordinal);
    }

    /// <summary>The arm the RAPID twin moves when the options give no model: it reaches the targets of the examples (Hello Robot).</summary>
    internal const string FallbackModel = "IRB 1600-8/1.45";

    /// <summary>The IO configuration of the twin: one DSQC 652-like board, DO_1…DO_16 and DI_1…DI_16, with AO_1…AO_4 and AI_1…AI_4.</summary>
    internal static readonly IReadOnlyList<(string Name, string Type)> Signals =
    [
        .. Enumerable.Range(1, 16).Select(i => ($"DO_{i}", "signaldo")),
        .. Enumerable.Range(1, 16).Select(i => ($"DI_{i}", "signaldi")),
        .. Enumerable.Range(1, 4).Select(i => ($"AO_{i}", "signalao")),
        .. Enumerable.Range(1, 4).Select(i => ($"AI_{i}", "signalai")),
    ];

    /// <summary>
    /// Where the twin's arm starts: the joints of the start point; without a model, the fallback arm's closest solution for the
    /// initial pose when one is given (else the initial joints).
    /// </summary>
    private Joints TwinStartJoints()
    {
        if (Model is not null || (_options.InitialPosition is null && _options.InitialRotation is null))
        {
            return State.Joints;
        }
        VirtualAbbState start = State;
        return RobotModels.Get(FallbackModel).Kinematics.Closest(new Pose(start.Position, start.Rotation), _options.InitialJoints)
            ?? throw new ArgumentException($"The {FallbackModel} (the arm without a model) cannot reach the initial pose {new Pose(start.Position, start.Rotation)}.");
    }

    /// <summary>The name of the monitor's task, as in the monitor's .pgf and the controller's configuration.</summary>
    internal const string MonitorTask = "T_MACHINA_MONITOR";

    private void StopTwin()
    {
        lock (_restartGate)
        {
            ReleaseTwinRequests();
            if (Twin is { } twin && !twin.StopTasks(TimeSpan.FromSeconds(10)))
            {
                RecordError("stopping: a RAPID task did not end within 10 s");
            }
            Twin?.RemoveTemporaryHome();
        }
    }
}
