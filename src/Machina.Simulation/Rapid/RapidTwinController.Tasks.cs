using System.Net;
using System.Net.Sockets;

namespace Machina.Simulation.Rapid;

/// <summary>
/// The controller's tasks running at once, as with the Multitasking option: each task's <c>main</c> runs on its own thread, PERS data
/// is shared, and a motion error that stops a task is posted to the error interrupts (IError) of every task, as the event log would.
/// </summary>
internal sealed partial class RapidTwinController
{
    private readonly List<TcpListener> _reserved = [];
    private readonly List<RapidSocketDevice> _sockets = [];
    private readonly List<Thread> _threads = [];
    private CancellationTokenSource? _stop;

    /// <summary>Raised (on the task's thread) when a task's run ends, with the task.</summary>
    public event Action<RapidTask>? TaskEnded;

    /// <summary>A program wrote to the event log (ErrWrite, ErrLog): the event's number and its title, as Robot Web Services list it.</summary>
    public event Action<int, string>? EventLogged;

    /// <summary>Tells <see cref="EventLogged"/> of an event a program wrote.</summary>
    internal void LogEvent(int code, string title) => EventLogged?.Invoke(code, title);

    /// <summary>
    /// Hands over a listener already listening on 127.0.0.1: the program's SocketListen on that address takes it instead of
    /// binding again, so that a test can choose free ports before the program runs.
    /// </summary>
    public void Reserve(TcpListener listener)
    {
        lock (_reserved)
        {
            _reserved.Add(listener);
        }
    }

    /// <summary>The reserved listener on <paramref name="endpoint"/>, removed from the reservations; null when there is none.</summary>
    internal TcpListener? TakeReserved(IPEndPoint endpoint)
    {
        lock (_reserved)
        {
            int i = _reserved.FindIndex(l => l.LocalEndpoint is IPEndPoint e && e.Port == endpoint.Port && e.Address.Equals(endpoint.Address));
            if (i < 0)
            {
                return null;
            }
            TcpListener listener = _reserved[i];
            _reserved.RemoveAt(i);
            return listener;
        }
    }

    /// <summary>Remembers a socket a program created, so that stopping the controller closes it.</summary>
    internal void Track(RapidSocketDevice socket)
    {
        lock (_sockets)
        {
            if (!_sockets.Contains(socket))
            {
                _sockets.Add(socket);
            }
        }
    }

    /// <summary>True once a program created a socket (our driver): then moves do not blend (docs/simulation.md).</summary>
    internal bool HasSockets
    {
        get
        {
            lock (_sockets)
            {
                return _sockets.Count > 0;
            }
        }
    }

    /// <summary>Starts <paramref name="entry"/> of every task that has it, each on its own thread; <see cref="StopTasks"/> ends them.</summary>
    public void StartTasks(string entry = "main")
    {
        RapidTask[] tasks;
        lock (_gate)
        {
            if (_stop is not null)
            {
                throw new InvalidOperationException("The tasks are already running.");
            }
            _stop = new CancellationTokenSource();
            tasks = [.. _tasks.Values];
        }
        CancellationToken token = _stop.Token;
        foreach (RapidTask task in tasks)
        {
            task.SetState(RapidProgramState.Running, null);
            var thread = new Thread(() => RunTask(task, entry, token)) { IsBackground = true, Name = "RAPID " + task.Name };
            _threads.Add(thread);
            thread.Start();
        }
    }

    /// <summary>Stops every task (the controller's stop), closes the sockets programs left open and waits up to <paramref name="timeout"/> for the threads.</summary>
    public bool StopTasks(TimeSpan timeout)
    {
        CancellationTokenSource? stop;
        lock (_gate)
        {
            stop = _stop;
        }
        stop?.Cancel();
        CloseSockets();
        lock (_reserved)
        {
            _reserved.ForEach(l => l.Stop());
            _reserved.Clear();
        }
        CloseFiles();
        bool joined = _threads.All(t => t.Join(timeout));
        // Once more after the tasks ended: a connection a task took between its stop and its end is closed too.
        CloseSockets();
        lock (_gate)
        {
            _stop = null;
        }
        stop?.Dispose();
        _threads.Clear();
        return joined;
    }

    /// <summary>Closes every socket the programs created (their connections, listeners and datagram sockets).</summary>
    private void CloseSockets()
    {
        lock (_sockets)
        {
            foreach (RapidSocketDevice s in _sockets)
            {
                s.Outbox?.Flush(); // what the tasks sent before the stop goes out first
                s.Connection?.Dispose();
                s.Listener?.Stop();
                s.Udp?.Dispose();
            }
        }
    }

    /// <summary>Waits up to <paramref name="timeout"/> for every task started by <see cref="StartTasks"/> to end by itself, then stops them; false when one had to be stopped.</summary>
    public bool StopTasksWhenEnded(TimeSpan timeout)
    {
        bool ended = _threads.All(t => t.Join(timeout));
        return StopTasks(TimeSpan.FromSeconds(10)) && ended;
    }

    /// <summary>Runs <paramref name="entry"/> of <paramref name="task"/> to its end and records how it ended (see <see cref="Run"/>).</summary>
    public RapidProgramState RunTask(RapidTask task, string entry, CancellationToken cancellation)
    {
        RapidRoutine? main = task.Program.Find(entry);
        if (main is not { Kind: RapidRoutineKind.Proc } || main.Parameters.Count > 0)
        {
            return End(task, RapidProgramState.Failed, $"Execution error: the task {task.Name} has no procedure '{entry}' without parameters", 0);
        }
        task.SetState(RapidProgramState.Running, null);
        task.CancellationToken = cancellation;
        try
        {
            RunCycles(task, main, cancellation);
            FinishMotion(task, cancellation);
            return End(task, RapidProgramState.Finished, null, 0);
        }
        catch (RapidHaltException halt)
        {
            FinishMotion(task, cancellation);
            return End(task, halt.Exit ? RapidProgramState.Finished : RapidProgramState.Stopped, null, 0);
        }
        catch (RapidRuntimeException ex)
        {
            string message = ex.Event > 0 ? $"{ex.Event} {ex.Reason} (line {ex.Line}, task {task.Name})" : $"{ex.Message} (task {task.Name})";
            return End(task, RapidProgramState.Failed, message, ex.Event);
        }
        catch (OperationCanceledException)
        {
            return End(task, RapidProgramState.Stopped, null, 0);
        }
        catch (Exception ex) when (ex is ObjectDisposedException or System.Net.Sockets.SocketException or InvalidOperationException)
        {
            // The controller closed a socket under a running instruction while stopping.
            return End(task, cancellation.IsCancellationRequested ? RapidProgramState.Stopped : RapidProgramState.Failed,
                cancellation.IsCancellationRequested ? null : $"Execution error: {ex.Message} (task {task.Name})", 0);
        }
    }

    /// <summary>The program ended after a move with a zone: the arm stops at its waypoint (a real controller makes it a stop point).</summary>
    private void FinishMotion(RapidTask task, CancellationToken cancellation)
    {
        if (task.IsMotionTask && !cancellation.IsCancellationRequested)
        {
            try
            {
                Arm.FinishBlend(cancellation);
            }
            catch (OperationCanceledException)
            {
                // Stopped while the arm went to its last waypoint: it stands where it was.
            }
        }
    }

    private RapidProgramState End(RapidTask task, RapidProgramState state, string? error, int eventNumber)
    {
        if (error is not null)
        {
            Pendant.Log(error);
        }
        RapidTask[] others = [];
        if (eventNumber > 0)
        {
            lock (_gate)
            {
                others = [.. _tasks.Values.Where(t => t != task)];
            }
        }
        // One step for whoever looks: the other tasks' error interrupts are queued as the task shows stopped. A monitor client
        // that saw the task stopped finds the trap ordered, and a host told by the trap finds the task stopped.
        task.SetState(state, error, () =>
        {
            foreach (RapidTask other in others)
            {
                other.PostError(eventNumber / 10_000, eventNumber % 10_000, 3);
            }
        });
        TaskEnded?.Invoke(task);
        return state;
    }
}
