namespace Machina.Simulation.Krl;

/// <summary>
/// Which threads run a submit interpreter, each with the line it runs: what both interpreters call does what the caller's
/// interpreter does (WAIT SEC and the end of an advance run: the submit interpreter moves no arm and keeps no program time of
/// the robot's), and an output a submit program writes is traced at its own line, not at the robot program's.
/// </summary>
internal sealed partial class KrlTwinController
{
    private readonly Lock _submitThreadsGate = new();

    /// <summary>The running submit interpreters' threads and lines; replaced whole under the gate, read without it.</summary>
    private (int Thread, KrlRunningLine Line)[] _submitThreads = [];

    /// <summary>True while a submit interpreter runs (<see cref="SubmitProgramState"/>).</summary>
    private bool SubmitsRunning => Volatile.Read(ref _submitThreads).Length > 0;

    /// <summary>True on a thread that runs a submit interpreter (<see cref="RunSubmit"/>).</summary>
    internal bool OnSubmitInterpreter => SubmitLineHere() is not null;

    /// <summary>The line of the submit interpreter this thread runs, or null on any other thread (the robot's, a host's, a reader's).</summary>
    private KrlRunningLine? SubmitLineHere()
    {
        (int Thread, KrlRunningLine Line)[] threads = Volatile.Read(ref _submitThreads);
        if (threads.Length > 0)
        {
            int id = System.Environment.CurrentManagedThreadId;
            foreach ((int thread, KrlRunningLine line) in threads)
            {
                if (thread == id)
                {
                    return line;
                }
            }
        }
        return null;
    }

    /// <summary>The calling thread runs a submit interpreter at <paramref name="line"/> until the result is disposed.</summary>
    private SubmitThread EnterSubmitThread(KrlRunningLine line)
    {
        lock (_submitThreadsGate)
        {
            Volatile.Write(ref _submitThreads, [.. _submitThreads, (System.Environment.CurrentManagedThreadId, line)]);
        }
        return new SubmitThread(this);
    }

    /// <summary>A submit interpreter's thread registered (<see cref="EnterSubmitThread"/>); disposed on that thread when it ends.</summary>
    private readonly struct SubmitThread(KrlTwinController controller) : IDisposable
    {
        public void Dispose()
        {
            lock (controller._submitThreadsGate)
            {
                int id = System.Environment.CurrentManagedThreadId;
                Volatile.Write(ref controller._submitThreads, [.. controller._submitThreads.Where(t => t.Thread != id)]);
            }
        }
    }
}
