using Machina.Simulation.Rapid;

namespace Machina.Simulation;

public sealed partial class VirtualAbbController
{
    /// <summary>Orders a restart of the RAPID tasks against the controller stopping (<see cref="StopTwin"/>).</summary>
    private readonly Lock _restartGate = new();

    /// <summary>The driver and monitor modules as loaded at start (task, file name, text): a restart loads them again, their data at their initial values.</summary>
    private readonly List<(string Task, string File, string Text)> _modules = [];

    /// <summary>True from a restart that loses the progress until the driver task runs again: the old program accepts no client.</summary>
    private bool _restarting;

    /// <summary>
    /// The fault plan's RestartLosingProgress, as a controller restart that loads the program again (RAPID's VARs, among them the
    /// driver's <c>lastExecutedId</c> and <c>lastReceivedId</c>, get their initial values): called on the driver task's thread,
    /// in its SocketSend of an acknowledgement. What the driver read and did not run is lost with it; the old program accepts no
    /// client from now on, and the tasks are stopped, the driver and monitor modules loaded again and the tasks started from main on another
    /// thread (a task cannot wait for its own end). A host that connects meanwhile is refused and connects again.
    /// </summary>
    private protected override void RestartingLosingProgress()
    {
        if (Twin is not { } twin)
        {
            return;
        }
        lock (Gate)
        {
            _restarting = true;
        }
        ReleaseTwinRequests();
        Run(token => Task.Run(() => RestartTasks(twin, token), CancellationToken.None));
    }

    private void RestartTasks(RapidTwinController twin, CancellationToken token)
    {
        lock (_restartGate)
        {
            if (token.IsCancellationRequested)
            {
                return;
            }
            if (!twin.StopTasks(TimeSpan.FromSeconds(10)))
            {
                RecordError("restarting: a RAPID task did not end within 10 s");
            }
            foreach ((string task, string file, string text) in _modules)
            {
                twin.LoadModuleFile(task, file, text, replace: true);
            }
            lock (Gate)
            {
                _restarting = false;
            }
            if (!token.IsCancellationRequested)
            {
                twin.StartTasks();
                Pendant("restarted: the RAPID tasks run again from main, the driver and monitor modules loaded again");
            }
        }
    }

    /// <summary>True while a restart is under way (the old driver program must not greet anyone).</summary>
    private bool IsRestarting
    {
        get
        {
            lock (Gate)
            {
                return _restarting;
            }
        }
    }
}
