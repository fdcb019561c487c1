namespace Machina.Simulation.Krl;

/// <summary>
/// Which threads run the submit interpreter, so that what both interpreters call (WAIT SEC, the end of an advance run) does only
/// what the caller's interpreter does: the submit interpreter moves no arm and keeps no program time of the robot's.
/// </summary>
internal sealed partial class KrlTwinController
{
    private readonly Lock _submitThreadsGate = new();
    private int[] _submitThreads = [];

    /// <summary>True on a thread that runs the submit interpreter (<see cref="RunSubmit"/>).</summary>
    internal bool OnSubmitInterpreter
    {
        get
        {
            int[] threads = Volatile.Read(ref _submitThreads);
            return threads.Length > 0 && Array.IndexOf(threads, System.Environment.CurrentManagedThreadId) >= 0;
        }
    }

    /// <summary>The calling thread runs the submit interpreter from now on.</summary>
    private void EnterSubmitThread()
    {
        lock (_submitThreadsGate)
        {
            Volatile.Write(ref _submitThreads, [.. _submitThreads, System.Environment.CurrentManagedThreadId]);
        }
    }

    /// <summary>The calling thread's submit interpreter ended.</summary>
    private void LeaveSubmitThread()
    {
        lock (_submitThreadsGate)
        {
            int id = System.Environment.CurrentManagedThreadId;
            Volatile.Write(ref _submitThreads, [.. _submitThreads.Where(t => t != id)]);
        }
    }
}
