using Machina.Simulation.Twin;

namespace Machina.Simulation.Krl;

/// <summary>
/// How a program's write of a variable wakes a WAIT FOR that reads it (in either interpreter: the submit interpreter sets a global
/// the robot program waits on): the variables that WAIT FOR and interrupt conditions read are marked when the program is loaded
/// (<see cref="KrlCell.WakeOnWrite"/>), and a write of one wakes the controller's waiters while a WAIT FOR waits. A KRC goes on
/// when the condition is TRUE; looking again every interpreter cycle is kept only for conditions that read something without
/// such a wake-up (a timer, a function, a system variable the controller updates).
/// </summary>
internal sealed class KrlWaitWake(TwinIo io)
{
    private int _waiting;

    /// <summary>A WAIT FOR starts waiting (before it reads the change count and looks at its condition).</summary>
    public void Waits() => Interlocked.Increment(ref _waiting);

    /// <summary>The WAIT FOR ended.</summary>
    public void Ends() => Interlocked.Decrement(ref _waiting);

    /// <summary>
    /// A marked variable was written: wakes the waiters when a WAIT FOR waits. The fence orders the write before the read of the
    /// count, as <see cref="Waits"/>'s interlocked increment orders the count before the waiter's look at the variable: either the
    /// waiter sees the new value or the writer sees the waiter.
    /// </summary>
    public void Wrote()
    {
        Interlocked.MemoryBarrier();
        if (Volatile.Read(ref _waiting) > 0)
        {
            io.Changed();
        }
    }
}
