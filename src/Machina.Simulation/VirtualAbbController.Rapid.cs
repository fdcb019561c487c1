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
        double rate = Math.Clamp(1 / _options.MonitorPeriod.TotalSeconds, 0.01, 250);
        foreach ((string file, string text) in AbbDriverModules.Create("127.0.0.1", Port, rate))
        {
            if (file.EndsWith(".mod", StringComparison.Ordinal))
            {
                twin.Task(file.Contains("monitor", StringComparison.Ordinal) ? MonitorTask : RapidTwinController.MotionTask).Load([(file, text)]);
            }
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
