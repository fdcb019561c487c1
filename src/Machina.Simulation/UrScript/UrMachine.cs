using Machina.Simulation.Twin;

namespace Machina.Simulation.UrScript;

/// <summary>A started thread of a program (the value <c>run</c> gives).</summary>
internal sealed class UrThreadHandle(string name, CancellationTokenSource stop)
{
    /// <summary>The thread's name.</summary>
    public string Name { get; } = name;

    /// <summary>Cancelled by <c>kill</c> or when the program stops.</summary>
    public CancellationTokenSource Stop { get; } = stop;

    /// <summary>The .NET thread that runs it.</summary>
    public Thread? Thread { get; set; }

    /// <summary>True once the thread's body ended (set under the machine's lock; its <see cref="Stop"/> may then be disposed).</summary>
    public bool Finished { get; set; }

    /// <inheritdoc/>
    public override string ToString() => $"thread {Name}";
}

/// <summary>
/// One running URScript program: its globals, its threads and the controller it runs on. Threads run one at a time, as in the
/// controller: a thread gives way to the others only in a blocking call (motion, sleep, sync, socket reads) or every few thousand
/// loop turns.
/// </summary>
internal sealed class UrMachine : IDisposable
{
    private const int LoopTurnsPerYield = 4096;
    private readonly object _gil = new();
    private readonly ThreadLocal<CancellationToken> _token = new();
    private readonly CancellationTokenSource _stop;
    private readonly List<UrThreadHandle> _threads = [];
    private Exception? _threadError;
    private int _turns;
    private long _steps;
    private readonly long _stepWork;

    /// <summary>The fewest steps that end the program: the verification's budget or a secondary program's step (none: long.MaxValue).</summary>
    private readonly long _stepLimit;
    private int _liveThreads;

    /// <summary>True once the program ends: no thread starts any more (set under the machine's lock).</summary>
    private bool _stopping;

    /// <summary>A machine for <paramref name="program"/> on <paramref name="controller"/>.</summary>
    public UrMachine(UrBoundProgram program, UrTwinController controller, CancellationToken cancellation)
    {
        Program = program;
        Limits = controller.Options.Limits;
        Controller = controller;
        Globals = new object?[program.Globals.Length];
        _stepLimit = Limits.MaxSteps > 0 ? Limits.MaxSteps : long.MaxValue;
        _stop = CancellationTokenSource.CreateLinkedTokenSource(cancellation);
    }

    /// <summary>The program.</summary>
    public UrBoundProgram Program { get; }

    /// <summary>The controller the program runs on (arm, IO, pendant).</summary>
    public UrTwinController Controller { get; }

    /// <summary>
    /// The sockets this program opened, by name. They are the program's own, as on a UR: they close when it ends, and a program
    /// that replaced it has its own (an old program still winding down never closes or reads the new one's connection).
    /// </summary>
    public Dictionary<string, UrSocket> Sockets { get; } = new(StringComparer.Ordinal);

    /// <summary>
    /// The sockets' network stack on the program's own thread (<see cref="Run"/>): what it writes on the virtual UR's driver
    /// connection is held until it is about to wait, after <see cref="TwinHeldSends.StatementBound"/> statements, and at its end.
    /// </summary>
    public TwinHeldSends Sends { get; } = new();

    /// <summary>The global variable slots.</summary>
    public object?[] Globals { get; }

    /// <summary>The line being run (for messages).</summary>
    public int CurrentLine { get; set; }

    /// <summary>The interpreter's budgets.</summary>
    public TwinLimits Limits { get; }

    /// <summary>
    /// What one controller step allows a secondary program (<see cref="UrTwinController"/>'s secondary programs): statements and
    /// loop turns counted together; past it the program stops with <see cref="TooMuchBehind"/>. 0 (a main program): no such bound.
    /// </summary>
    public long StepWork
    {
        get => _stepWork;
        init
        {
            _stepWork = value;
            _stepLimit = Math.Min(_stepLimit, value > 0 ? value : long.MaxValue);
        }
    }

    /// <summary>A UR's error for a program that keeps the real-time thread past its step (the Script Manual's "Secondary Program Limitations").</summary>
    public const string TooMuchBehind = "Runtime is too much behind";

    /// <summary>Called before each statement: the line being run, and the program's step budget.</summary>
    public void Step(int line)
    {
        CurrentLine = line;
        Sends.Statement();
        if (++_steps > _stepLimit)
        {
            OverBudget(line);
        }
    }

    /// <summary>The program ran past its step budget (the verification's) or a secondary program past one controller step.</summary>
    private void OverBudget(int line)
    {
        if (_stepWork > 0 && _steps > _stepWork)
        {
            throw new UrRuntimeException(line, $"{TooMuchBehind} (a secondary program must end within one controller step: the twin allows it {_stepWork:N0} statements and loop turns)");
        }
        throw new UrRuntimeException(line, $"the program ran more than {Limits.MaxSteps:N0} statements (the verification's step budget): an endless loop?");
    }

    /// <summary>Cancelled when the program or the calling thread is stopped.</summary>
    public CancellationToken Cancellation => _token.IsValueCreated ? _token.Value : _stop.Token;

    /// <summary>Runs the program to its end on the calling thread; a runtime error or a stop ends it with an exception.</summary>
    public void Run()
    {
        _token.Value = _stop.Token;
        Sends.Own();
        lock (_gil)
        {
            try
            {
                var frame = new UrFrame(this, new object?[Program.Entry?.LocalCount ?? 0], 0, new UrScratch());
                if (Program.Statements.Count > 0)
                {
                    UrStmt.Run(Program.Statements, frame);
                }
                else if (Program.Entry is not null)
                {
                    Program.Entry.Invoke(this, Program.Entry.Line, [], 0);
                }
            }
            catch (UrHaltSignal)
            {
            }
            catch (OperationCanceledException) when (_threadError is not null)
            {
                throw _threadError;
            }
            catch (Exception e) when (IsTwinFault(e))
            {
                throw TwinFault(e);
            }
            finally
            {
                // The bytes are on the wire before the program shows ended; no later thread with this id holds anything.
                Sends.Flush();
                Sends.Disown();
                StopThreads();
                // The program's threads are all gone: a speed motion one of them left going is no thread's now (the program's end
                // stops it, UrTwinController.SettleCoast).
                _stop.Cancel();
            }
            if (_threadError is not null)
            {
                throw _threadError;
            }
        }
    }

    /// <summary>Called every loop turn: stops when asked, and lets the other threads run now and then.</summary>
    public void LoopTick()
    {
        Cancellation.ThrowIfCancellationRequested();
        if (_stepWork > 0 && ++_steps > _stepLimit)
        {
            OverBudget(CurrentLine); // a secondary program's loop turns count too: an empty loop never ends its step
        }
        if (++_turns >= LoopTurnsPerYield && _threads.Count > 0)
        {
            _turns = 0;
            TwinWait.Blocking();
            Unlocked(() => Thread.Yield());
            // Killed (or stopped) while the others ran: a killed thread runs no further statement (the Script Manual's kill).
            Cancellation.ThrowIfCancellationRequested();
        }
    }

    /// <summary>Runs a blocking call (motion, wait, socket read) with the other threads allowed to run meanwhile.</summary>
    public T Unlocked<T>(Func<T> call)
    {
        Monitor.Exit(_gil);
        try
        {
            return call();
        }
        finally
        {
            Monitor.Enter(_gil);
        }
    }

    /// <summary>
    /// As <see cref="Unlocked{T}(Func{T})"/> without a delegate: the other threads may run until the scope is disposed
    /// (<c>using (m.Unlock()) { … }</c>), which takes the machine's lock back, also when the call throws.
    /// </summary>
    public UnlockedScope Unlock()
    {
        Monitor.Exit(_gil);
        return new UnlockedScope(_gil);
    }

    /// <summary>The scope of <see cref="Unlock"/>: its disposal takes the machine's lock back.</summary>
    public readonly struct UnlockedScope(object gil) : IDisposable
    {
        /// <summary>Takes the machine's lock back.</summary>
        public void Dispose() => Monitor.Enter(gil);
    }

    /// <summary>Starts <paramref name="thread"/> and gives its handle.</summary>
    public UrThreadHandle StartThread(UrFunction thread, int line)
    {
        if (_stopping)
        {
            throw new OperationCanceledException("the program is ending");
        }
        // Threads that ended leave the list (their handles stay valid for join and kill): a loop of run and join stays small.
        _threads.RemoveAll(t =>
        {
            if (t.Finished)
            {
                t.Stop.Dispose();
            }
            return t.Finished;
        });
        if (_liveThreads >= Limits.MaxThreads)
        {
            throw new UrRuntimeException(line, $"more than {Limits.MaxThreads} threads are running (the twin's limit): join or kill one before starting '{thread.Name}'");
        }
        _liveThreads++;
        var handle = new UrThreadHandle(thread.Name, CancellationTokenSource.CreateLinkedTokenSource(_stop.Token));
        var worker = new Thread(() => ThreadBody(thread, handle)) { IsBackground = true, Name = "URScript thread " + thread.Name };
        handle.Thread = worker;
        _threads.Add(handle);
        worker.Start();
        return handle;
    }

    private void ThreadBody(UrFunction thread, UrThreadHandle handle)
    {
        _token.Value = handle.Stop.Token;
        lock (_gil)
        {
            try
            {
                thread.Invoke(this, thread.Line, [], 0);
            }
            catch (OperationCanceledException)
            {
            }
            catch (UrHaltSignal)
            {
                _stop.Cancel();
            }
            catch (Exception e) when (e is UrRuntimeException or TwinMotionException)
            {
                _threadError ??= e;
                _stop.Cancel();
            }
            catch (Exception e) when (IsTwinFault(e))
            {
                _threadError ??= TwinFault(e);
                _stop.Cancel();
            }
            finally
            {
                _liveThreads--;
                handle.Finished = true;
                handle.Stop.Cancel(); // a speed motion the thread left going is no live thread's: another may take it over
            }
        }
    }

    /// <summary>
    /// True for what the twin's own code throws on a value it did not foresee (an argument out of a .NET call's range, an overflow,
    /// a cast): the program's error, never the process's.
    /// </summary>
    private static bool IsTwinFault(Exception e) => e is ArgumentException or ArithmeticException or InvalidCastException or IndexOutOfRangeException;

    /// <summary>The runtime error that stops the program for a fault of the twin's own code, at the line that ran.</summary>
    private UrRuntimeException TwinFault(Exception e) => new(CurrentLine, "the twin cannot run this statement: " + e.Message);

    /// <summary><c>join</c>: waits for the thread to end.</summary>
    public void JoinThread(UrThreadHandle handle, int line)
    {
        CancellationToken token = Cancellation;
        TwinWait.Blocking();
        Unlocked(() =>
        {
            while (!handle.Thread!.Join(20))
            {
                token.ThrowIfCancellationRequested();
            }
            return 0;
        });
    }

    /// <summary><c>kill</c>: stops the thread (it ends at its next blocking call or loop turn).</summary>
    public void KillThread(UrThreadHandle handle)
    {
        if (!handle.Finished)
        {
            handle.Stop.Cancel();
        }
    }

    private void StopThreads()
    {
        // Under the lock: once _stopping is set no thread starts, so the list below is every thread there will be.
        _stopping = true;
        UrThreadHandle[] running = [.. _threads.Where(t => !t.Finished)];
        foreach (UrThreadHandle thread in running)
        {
            thread.Stop.Cancel();
        }
        if (running.Length > 0)
        {
            Unlocked(() =>
            {
                foreach (UrThreadHandle thread in running)
                {
                    thread.Thread!.Join(TimeSpan.FromSeconds(5));
                }
                return 0;
            });
        }
    }

    /// <inheritdoc/>
    public void Dispose()
    {
        if (_threads.Any(t => t.Thread!.IsAlive))
        {
            return; // a thread that did not stop in time still reads these; the collector takes them after it
        }
        _stop.Dispose();
        _token.Dispose();
        foreach (UrThreadHandle thread in _threads)
        {
            thread.Stop.Dispose();
        }
    }
}
