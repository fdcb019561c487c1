using System.Globalization;
using System.Net.Sockets;
using Machina.Simulation.Rapid;

namespace Machina.Simulation;

public sealed partial class VirtualAbbController
{
    /// <summary>The RAPID controller that runs Machina's driver and monitor modules (<see cref="VirtualAbbControllerOptions.RunsRapid"/>), else null.</summary>
    internal RapidTwinController? Twin { get; private set; }

    /// <summary>
    /// Loads drivers/abb as <c>machina drivers abb</c> writes them (driver in T_ROB1 on <see cref="Port"/>, monitor in
    /// T_MACHINA_MONITOR on port + 1) and starts both tasks; their SocketListen takes the ports bound here.
    /// </summary>
    private void StartTwin(TcpListener driver, TcpListener monitor)
    {
        var twin = new RapidTwinController(new RapidTwinOptions
        {
            Model = Model!,
            StartJoints = _options.InitialJoints,
            Time = Clock,
            RealTime = !_options.InstantExecution,
        });
        // The shipped files with their placeholders filled, as an installer writes them (the host's AbbDriverModules does the same).
        string interval = Math.Max(0.004, _options.MonitorPeriod.TotalSeconds).ToString("0.###", CultureInfo.InvariantCulture);
        foreach ((string file, string task, int port) in new[] { ("machina_abb_driver.mod", RapidTwinController.MotionTask, Port), ("machina_abb_monitor.mod", MonitorTask, MonitorPort) })
        {
            string text = DriverFiles.Fill(DriverFiles.Read(file),
                ("HOSTNAME", "127.0.0.1"), ("PORT", port.ToString(CultureInfo.InvariantCulture)), ("MONITOR_INTERVAL", interval));
            twin.Task(task).Load([(file, text)]);
        }
        twin.Pendant.Logged += line =>
        {
            if (line.StartsWith("Execution error", StringComparison.Ordinal))
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

    /// <summary>The name of the monitor's task, as in the monitor's .pgf and the controller's configuration.</summary>
    internal const string MonitorTask = "T_MACHINA_MONITOR";

    private void StopTwin()
    {
        if (Twin is { } twin && !twin.StopTasks(TimeSpan.FromSeconds(10)))
        {
            RecordError("stopping: a RAPID task did not end within 10 s");
        }
    }
}
