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
    private CancellationTokenSource? _programStop;
    private Thread? _programThread;
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
                return;
            }
            while (intake.TakeProgram() is { } program)
            {
                programs.Add(program);
            }
        }
        foreach (string program in programs)
        {
            ProgramReceived?.Invoke(program);
            Start(program);
        }
    }

    /// <summary>
    /// Compiles <paramref name="text"/> and, when it compiles, stops the running program and starts this one on its own thread.
    /// A program that does not compile is refused: the running one goes on, and <c>Error</c> says why.
    /// </summary>
    /// <returns>True when the program started.</returns>
    public bool Start(string text)
    {
        UrBoundProgram program;
        try
        {
            program = Compile(text, Options.Limits);
        }
        catch (UrCompileException e)
        {
            Fail(e.Message);
            return false;
        }
        if (Options.StartRefusal?.Invoke() is string refusal)
        {
            Fail(refusal);
            return false;
        }
        StopProgram();
        if (Options.HeldBySafety?.Invoke() != true)
        {
            Release(); // the paused program is gone: the new one is not paused
        }
        Modes.Reset();
        var stop = new CancellationTokenSource();
        string header = text.TrimStart();
        int paren = header.IndexOf('(', StringComparison.Ordinal);
        bool named = header.StartsWith("def ", StringComparison.Ordinal) || header.StartsWith("sec ", StringComparison.Ordinal);
        Thread thread;
        lock (_gate)
        {
            int number = ++_programs;
            thread = new Thread(() => RunBound(program, number, stop.Token)) { IsBackground = true, Name = "URScript program" };
            _programName = named && paren > 4 ? header[4..paren].Trim() : null;
            _programStop = stop;
            _programThread = thread;
            ProgramStatus.Set(UrProgramState.Running, null);
            // Started before the gate opens: another connection's program may stop this one at once, and joins it.
            thread.Start();
        }
        StateChanged?.Invoke();
        return true;
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
        CancellationTokenSource? stop;
        Thread? thread;
        lock (_gate)
        {
            stop = _programStop;
            thread = _programThread;
            _programStop = null;
            _programThread = null;
        }
        if (stop is null)
        {
            return;
        }
        stop.Cancel();
        if (thread == Thread.CurrentThread || thread is null || thread.Join(StopTimeout))
        {
            stop.Dispose(); // a program still winding down may still wait on its token
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
                ThreadPool.QueueUserWorkItem(static twin => twin.StopOnPath(), this, preferLocal: false);
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
    /// motion had brought it (not back at the motion's start); the hold used for that is cleared after.
    /// </summary>
    public void StopOnPath()
    {
        if (State == UrProgramState.Running && Hold())
        {
            // The program's thread records where the arm stands when the hold reaches the motion (bounded: it does at once).
            WaitUntilStanding(TimeSpan.FromSeconds(5));
            StopProgram();
            Release();
            return;
        }
        StopProgram();
    }

    /// <inheritdoc/>
    public void Dispose()
    {
        StopProgram();
        Watchdog.Dispose();
    }
}
