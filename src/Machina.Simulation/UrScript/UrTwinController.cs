using Machina.Simulation.Twin;

namespace Machina.Simulation.UrScript;

/// <summary>
/// A UR controller that runs URScript: programs are compiled before they run (a mistake refuses the whole program, with its
/// line), run on the twin arm with the model's kinematics, and a runtime error stops the program with the controller's message.
/// Text arrives as on the controller's script port: a program starts as soon as its top-level <c>def … end</c> is complete,
/// and a new program stops the one running.
/// </summary>
internal sealed partial class UrTwinController : TwinController<UrTwinOptions, UrProgramState>, IDisposable
{
    /// <summary>Largest program text accepted (a program above this size is refused).</summary>
    public const int MaxProgramLength = 16 * 1024 * 1024;

    private readonly Lock _gate = new();
    private readonly UrScriptIntake _incoming = new();

    /// <summary>
    /// The controller's own end (<see cref="Shutdown"/>, <see cref="Dispose"/>): it ends the waits of what the controller started by
    /// itself (an RTDE watchdog's stop) and of a program's end that a new program or a stop waits for.
    /// </summary>
    private readonly CancellationTokenSource _shutdown = new();
    private CancellationTokenSource? _programStop;
    private Thread? _programThread;
    private Task? _programEnded;
    private int _programs;
    private string? _programName;

    /// <summary>A controller with <paramref name="options"/> (UR5e, not real-time, by default).</summary>
    public UrTwinController(UrTwinOptions? options = null)
        : base(options ?? new UrTwinOptions(), interpolates: false)
    {
        Random = new Random(Options.RandomSeed);
        Io = new TwinIo();
        Io.AddBits(UrIoBanks.StandardIn, 8);
        Io.AddBits(UrIoBanks.StandardOut, 8);
        Io.AddBits(UrIoBanks.ConfigurableIn, 8);
        Io.AddBits(UrIoBanks.ConfigurableOut, 8);
        Io.AddBits(UrIoBanks.ToolIn, 2);
        Io.AddBits(UrIoBanks.ToolOut, 2);
        Io.AddNumbers(UrIoBanks.AnalogIn, 2);
        Io.AddNumbers(UrIoBanks.AnalogOut, 2);
        Io.AddNumbers(UrIoBanks.ToolAnalogIn, 2);
        Io.AddBits(UrIoBanks.Flags, 33);
        Io.AddBits(UrIoBanks.InputBoolRegisters, 128);
        Io.AddBits(UrIoBanks.OutputBoolRegisters, 128);
        Io.AddNumbers(UrIoBanks.InputIntRegisters, 48);
        Io.AddNumbers(UrIoBanks.OutputIntRegisters, 48);
        Io.AddNumbers(UrIoBanks.InputFloatRegisters, 48);
        Io.AddNumbers(UrIoBanks.OutputFloatRegisters, 48);
        Watchdog = new UrRtdeWatchdog(Options.Time, OnWatchdog);
    }

    /// <summary>Inputs, outputs and RTDE registers.</summary>
    public TwinIo Io { get; }

    /// <summary>Force mode, freedrive, gravity and the RTDE watchdog as the program set them.</summary>
    public UrControlModes Modes { get; } = new();

    /// <summary>The RTDE watchdogs the running program set (<c>rtde_set_watchdog</c>).</summary>
    public UrRtdeWatchdog Watchdog { get; }

    /// <summary>Raised for each complete program taken from the received text (before it is compiled and started).</summary>
    public event Action<string>? ProgramReceived;

    /// <summary>Raised when a runtime error stops the program, with its line and reason, before its sockets close (on the program's thread).</summary>
    public event Action<int, string>? RuntimeError;

    /// <summary>Raised after a program started or ended (on the thread that started or ran it).</summary>
    public event Action? StateChanged;

    /// <summary>The source of <c>random()</c> (seeded from the options, so a run can be repeated).</summary>
    internal Random Random { get; }

    /// <summary>
    /// How long a new program waits for the one it replaces (or a stop) to end. A program that takes longer (a loaded machine)
    /// winds down beside the new one, touching only what is its own: its sockets, never the new program's state.
    /// </summary>
    internal TimeSpan StopTimeout { get; set; } = TimeSpan.FromSeconds(10);

    /// <summary>A test's hook: called on a program's thread as it ends, before its sockets close, with the program's number (1 for the first).</summary>
    internal Action<int>? Ending { get; set; }

    /// <summary>The name of the last program started with a <c>def</c> or <c>sec</c> (null for a one-line program or none).</summary>
    public string? ProgramName
    {
        get
        {
            lock (_gate)
            {
                return _programName;
            }
        }
    }

    /// <summary>How many programs were started (refused ones not counted).</summary>
    public int ProgramsStarted
    {
        get
        {
            lock (_gate)
            {
                return _programs;
            }
        }
    }

    /// <summary>Parses and binds a program within <paramref name="limits"/> (the default ones when null); throws <see cref="UrCompileException"/> for the first mistake.</summary>
    public static UrBoundProgram Compile(string text, TwinLimits? limits = null)
    {
        limits ??= TwinLimits.Default;
        long most = Math.Min(MaxProgramLength, limits.MaxProgramChars);
        if (text.Length > most)
        {
            throw new UrCompileException(1, $"the program is longer than {most} characters");
        }
        return UrBinder.Bind(UrParser.Parse(text, limits), UrBuiltins.All);
    }

    /// <summary>
    /// Text as it arrives on the script port, in any pieces. A top-level <c>def … end</c> starts when its <c>end</c> line is there
    /// (a line break after it is not needed); the call line that often follows it belongs to that program and is skipped;
    /// another complete line outside a definition runs as a one-line program.
    /// </summary>
    public void Receive(string text) => Receive(text, _incoming);

    /// <summary>
    /// Text as it arrives on one connection to a script port, split into programs by that connection's own
    /// <paramref name="intake"/>: the unfinished text of one client is never joined to another's (as on the controller, which
    /// reads each connection apart).
    /// </summary>
    public void Receive(string text, UrScriptIntake intake)
    {
        foreach (string program in TakePrograms(text, intake))
        {
            ProgramReceived?.Invoke(program);
            Start(program);
        }
    }

    /// <summary>
    /// As <see cref="Receive(string, UrScriptIntake)"/> without holding the calling thread while a program it replaces ends (a
    /// script connection's reader, on a thread-pool thread): <paramref name="cancellation"/> (the controller's stop) ends that
    /// wait early, and the program is replaced all the same.
    /// </summary>
    public async Task ReceiveAsync(string text, UrScriptIntake intake, CancellationToken cancellation)
    {
        foreach (string program in TakePrograms(text, intake))
        {
            ProgramReceived?.Invoke(program);
            await StartAsync(program, cancellation).ConfigureAwait(false);
        }
    }

    /// <summary>Adds <paramref name="text"/> to <paramref name="intake"/> and takes out the programs it completed (none when it grew too long: that fails).</summary>
    private List<string> TakePrograms(string text, UrScriptIntake intake)
    {
        List<string> programs = [];
        lock (_gate)
        {
            intake.Append(text);
            if (intake.Length > MaxProgramLength)
            {
                intake.Clear();
                string error = $"Compile error: line 1: the program is longer than {MaxProgramLength} characters";
                ProgramStatus.Set(UrProgramState.Failed, error);
                Pendant.Log(error);
                return programs;
            }
            while (intake.TakeProgram() is { } program)
            {
                programs.Add(program);
            }
        }
        return programs;
    }

    /// <summary>
    /// Compiles <paramref name="text"/> and, when it compiles, stops the running program and starts this one on its own thread.
    /// A program that does not compile is refused: the running one goes on, and <c>Error</c> says why.
    /// </summary>
    /// <returns>True when the program started.</returns>
    public bool Start(string text)
    {
        if (Startable(text) is not { } program)
        {
            return false;
        }
        if (program.IsSecondary)
        {
            LaunchSecondary(program); // beside the main program, which goes on
            return true;
        }
        StopProgram();
        Launch(program, text);
        return true;
    }

    /// <summary>
    /// As <see cref="Start"/> without holding the calling thread while the running program ends (<see cref="StopProgramAsync"/>):
    /// <paramref name="cancellation"/> ends that wait early, and the new program starts all the same.
    /// </summary>
    /// <returns>True when the program started.</returns>
    public async Task<bool> StartAsync(string text, CancellationToken cancellation)
    {
        if (Startable(text) is not { } program)
        {
            return false;
        }
        if (program.IsSecondary)
        {
            LaunchSecondary(program); // beside the main program, which goes on
            return true;
        }
        await StopProgramAsync(cancellation).ConfigureAwait(false);
        Launch(program, text);
        return true;
    }

    /// <summary>The compiled program when it compiles and the controller takes it now; else null (it failed, with why).</summary>
    private UrBoundProgram? Startable(string text)
    {
        UrBoundProgram program;
        try
        {
            program = Compile(text, Options.Limits);
        }
        catch (UrCompileException e)
        {
            Fail(e.Message);
            return null;
        }
        if (Options.StartRefusal?.Invoke() is string refusal)
        {
            Fail(refusal);
            return null;
        }
        return program;
    }

    /// <summary>Starts <paramref name="program"/> (from <paramref name="text"/>) on a thread of its own, once the one it replaces was stopped.</summary>
    private void Launch(UrBoundProgram program, string text)
    {
        if (Options.HeldBySafety?.Invoke() != true)
        {
            Release(); // the paused program is gone: the new one is not paused
        }
        Modes.Reset();
        var stop = new CancellationTokenSource();
        string header = text.TrimStart();
        int paren = header.IndexOf('(', StringComparison.Ordinal);
        bool named = header.StartsWith("def ", StringComparison.Ordinal) || header.StartsWith("sec ", StringComparison.Ordinal);
        // Completed by the program's thread as its last act: what an awaited stop waits for instead of joining the thread.
        var ended = new TaskCompletionSource(TaskCreationOptions.RunContinuationsAsynchronously);
        lock (_gate)
        {
            int number = ++_programs;
            var thread = new Thread(() =>
            {
                try
                {
                    RunBound(program, number, stop.Token);
                }
                finally
                {
                    ended.TrySetResult();
                }
            }) { IsBackground = true, Name = "URScript program" };
            _programName = named && paren > 4 ? header[4..paren].Trim() : null;
            _programStop = stop;
            _programThread = thread;
            _programEnded = ended.Task;
            ProgramStatus.Set(UrProgramState.Running, null);
            // Started before the gate opens: another connection's program may stop this one at once, and joins it.
            thread.Start();
        }
        StateChanged?.Invoke();
    }

    /// <summary>Compiles and runs <paramref name="text"/> on the calling thread to its end; gives how it ended.</summary>
    public UrProgramState Run(string text, CancellationToken cancellation = default)
    {
        UrBoundProgram program;
        try
        {
            program = Compile(text, Options.Limits);
        }
        catch (UrCompileException e)
        {
            Fail(e.Message);
            return UrProgramState.Failed;
        }
        StopProgram();
        int number;
        lock (_gate)
        {
            ProgramStatus.Set(UrProgramState.Running, null);
            number = ++_programs;
        }
        RunBound(program, number, cancellation);
        return State;
    }

    /// <summary>Waits until no program runs (or the time is up); true when none runs.</summary>
    public bool WaitForEnd(TimeSpan timeout)
    {
        Thread? thread;
        lock (_gate)
        {
            thread = _programThread;
        }
        return thread is null || thread.Join(timeout);
    }

    /// <summary>Stops the running program, if any, and waits for it to end.</summary>
    public void StopProgram()
    {
        (CancellationTokenSource? stop, Thread? thread, Task? ended) = TakeProgram();
        if (stop is null)
        {
            return;
        }
        stop.Cancel();
        if (thread == Thread.CurrentThread || ended is null || EndsWithinBlocking(ended, StopTimeout, _shutdown.Token))
        {
            stop.Dispose(); // a program still winding down may still wait on its token
        }
    }

    /// <summary>
    /// Ends the controller's own waits at once (its host is stopping): an RTDE watchdog's stop in progress no longer waits for
    /// the arm to stand or the program to end, nor does a program's stop that the controller does by itself; the program is
    /// stopped all the same and winds down by itself. <see cref="Dispose"/> does this too.
    /// </summary>
    public void Shutdown() => _shutdown.Cancel();

    /// <summary>
    /// As <see cref="StopProgram"/> without holding the calling thread while the program ends: awaits the task the program's
    /// thread completes as its last act (at most <see cref="StopTimeout"/>, as the join). <paramref name="cancellation"/> ends
    /// the wait early; the program is stopped all the same and winds down by itself.
    /// </summary>
    public async Task StopProgramAsync(CancellationToken cancellation)
    {
        (CancellationTokenSource? stop, Thread? thread, Task? ended) = TakeProgram();
        if (stop is null)
        {
            return;
        }
        stop.Cancel();
        if (thread == Thread.CurrentThread || ended is null || await EndsWithin(ended, StopTimeout, cancellation).ConfigureAwait(false))
        {
            stop.Dispose(); // a program still winding down may still wait on its token
        }
    }

    /// <summary>Takes the running program's stop, thread and end (nulls when none runs): it is no longer the one to stop.</summary>
    private (CancellationTokenSource? Stop, Thread? Thread, Task? Ended) TakeProgram()
    {
        lock (_gate)
        {
            var taken = (_programStop, _programThread, _programEnded);
            _programStop = null;
            _programThread = null;
            _programEnded = null;
            return taken;
        }
    }

    /// <summary>True when <paramref name="task"/> ends within <paramref name="timeout"/>; false after it, or when <paramref name="cancellation"/> ends the wait first.</summary>
    private static async Task<bool> EndsWithin(Task task, TimeSpan timeout, CancellationToken cancellation)
    {
        try
        {
            await task.WaitAsync(timeout, cancellation).ConfigureAwait(false);
            return true;
        }
        catch (TimeoutException)
        {
            return false;
        }
        catch (OperationCanceledException) when (cancellation.IsCancellationRequested)
        {
            return false;
        }
    }

    /// <summary>As <see cref="EndsWithin(Task, TimeSpan, CancellationToken)"/>, blocking the calling thread (a twin's wait, <see cref="TwinWait"/>).</summary>
    private static bool EndsWithinBlocking(Task task, TimeSpan timeout, CancellationToken cancellation)
    {
        try
        {
            return task.IsCompleted || TwinWait.For(task, timeout, cancellation);
        }
        catch (OperationCanceledException) when (cancellation.IsCancellationRequested)
        {
            return false;
        }
    }

    /// <summary>True while program <paramref name="number"/> is the last one started (call under the gate).</summary>
    private bool IsCurrent(int number) => _programs == number;

    private void RunBound(UrBoundProgram program, int number, CancellationToken cancellation)
    {
        UrProgramState end = UrProgramState.Failed;
        string? error = null;
        PendingBlend = null;
        using (var machine = new UrMachine(program, this, cancellation))
        {
            try
            {
                machine.Run();
                if (TakeBlend() is { } blend)
                {
                    FinishBlend(blend, cancellation); // the program's last motion ends at its waypoint
                }
                end = UrProgramState.Finished;
            }
            catch (UrRuntimeException e)
            {
                end = UrProgramState.Failed;
                error = e.Message;
                bool current;
                lock (_gate)
                {
                    current = IsCurrent(number);
                }
                if (current)
                {
                    RuntimeError?.Invoke(e.Line, e.Reason);
                }
            }
            catch (OperationCanceledException)
            {
                end = UrProgramState.Stopped;
            }
            finally
            {
                Ending?.Invoke(number);
                // The program has stopped before its sockets close, as on a UR: whoever sees a socket close and asks
                // the controller finds the program already stopped. A program replaced while it wound down (it outlived
                // StopTimeout) changes nothing of its successor's: it closes only its own sockets.
                bool current;
                lock (_gate)
                {
                    current = IsCurrent(number);
                    if (current)
                    {
                        ProgramStatus.Change(s => s == UrProgramState.Running ? end : null, error);
                    }
                }
                if (current)
                {
                    PendingBlend = null;
                    Watchdog.Clear(); // "All watchdogs are removed on program stop"
                }
                SettleCoast(); // a motion whose thread the end killed stops where it is (only a killed one: a successor's runs on)
                if (error is not null && current)
                {
                    Pendant.Log(error);
                }
                foreach (UrSocket socket in machine.Sockets.Values)
                {
                    socket.Dispose();
                }
                machine.Sockets.Clear();
            }
        }
        StateChanged?.Invoke();
    }

    private void Fail(string message)
    {
        // A running program goes on: only the refused one failed.
        ProgramStatus.Change(s => s == UrProgramState.Running ? s : UrProgramState.Failed, message);
        Pendant.Log(message);
    }

    /// <summary>
    /// A watchdog ran out (on its timer's thread): the pendant says so, and the program is held (<c>pause</c>) or stopped where
    /// the arm stands (<c>stop</c>) from another thread, so that the timer (a test's manual clock) does not wait for the program.
    /// </summary>
    private void OnWatchdog(string action, string message)
    {
        if (State != UrProgramState.Running)
        {
            return;
        }
        Pendant.Log(message);
        switch (action)
        {
            case "pause":
                Hold();
                break;
            case "stop":
                // Its waits (the arm standing, the program's end) end when the controller does (Shutdown): a host stopping
                // (Ctrl+C on `machina sim ur`) does not wait for them.
                ThreadPool.QueueUserWorkItem(static twin => _ = twin.StopOnPathAsync(twin._shutdown.Token), this, preferLocal: false);
                break;
        }
    }

    /// <summary>Raised when the program calls <c>protective_stop()</c>; without a handler the program is only held.</summary>
    public event Action? ProtectiveStopRequested;

    /// <summary><c>protective_stop()</c>: the controller's protective stop (its handler holds the program), or a hold.</summary>
    public void RequestProtectiveStop()
    {
        if (ProtectiveStopRequested is { } handler)
        {
            handler();
        }
        else
        {
            Hold();
        }
    }

    /// <summary>
    /// Stops the program as a UR's stop does: the arm decelerates on its path and the program ends, so the arm stands where the
    /// motion had brought it (not back at the motion's start); the hold used for that is cleared after. Awaited, it holds no
    /// thread while the hold reaches the motion and the program's thread ends (the dashboard's <c>stop</c>, <c>load</c> and
    /// <c>power off</c>, the primary <c>stop program</c>, an RTDE watchdog's <c>stop</c>: thread-pool threads). The task
    /// completes once the program has ended (or <see cref="StopTimeout"/> passed); <paramref name="cancellation"/> (the
    /// controller's stop) ends those waits early, and the program is stopped all the same.
    /// </summary>
    public async Task StopOnPathAsync(CancellationToken cancellation)
    {
        if (State == UrProgramState.Running && Hold())
        {
            // The program's thread records where the arm stands when the hold reaches the motion (bounded: it does at once).
            try
            {
                await WaitUntilStandingAsync(TimeSpan.FromSeconds(5), cancellation).ConfigureAwait(false);
            }
            catch (OperationCanceledException) when (cancellation.IsCancellationRequested)
            {
            }
            await StopProgramAsync(cancellation).ConfigureAwait(false);
            Release();
            return;
        }
        await StopProgramAsync(cancellation).ConfigureAwait(false);
    }

    /// <inheritdoc/>
    public void Dispose()
    {
        _secondaryStop.Cancel();
        StopProgram(); // at most StopTimeout, or until Shutdown (from another thread, or before: then it does not wait)
        Shutdown();
        Watchdog.Dispose();
    }
}
