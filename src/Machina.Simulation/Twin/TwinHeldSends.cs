using System.Runtime.CompilerServices;

namespace Machina.Simulation.Twin;

/// <summary>
/// The connections on which one program thread's sends are held (<see cref="TwinHeldOutbox"/>), and when they go out: when the
/// thread is about to block in any wait (<see cref="TwinWait.Blocking"/>), after <see cref="StatementBound"/> statements without
/// one, and when its run ends. A RAPID task has one, the KRL robot interpreter one (its EthernetKRL driver channel): what the
/// thread that <see cref="Own">owns</see> it writes is held, what other threads write goes out at once. Used on that thread (its
/// end may be recorded from another: the list is locked).
/// </summary>
internal sealed class TwinHeldSends
{
    /// <summary>
    /// How many statements a task runs after its first held send before the held bytes go out without a wait: a program that
    /// sends and then computes still gets its bytes out within so many statements (the driver runs a burst of requests in far
    /// fewer, and then waits in SocketReceive).
    /// </summary>
    public const int StatementBound = 1000;

    private readonly Lock _gate = new();
    private readonly List<TwinHeldOutbox> _holding = [];
    private readonly Action _flush;
    private bool _any;
    private int _budget;
    private int _owner = -1;

    /// <summary>A task's list, empty.</summary>
    public TwinHeldSends() => _flush = Flush;

    /// <summary>True on the thread that owns the list (its writes are held).</summary>
    public bool OwnedByCurrentThread => Volatile.Read(ref _owner) == Environment.CurrentManagedThreadId;

    /// <summary>Makes the calling thread the owner: the program's thread, when it accepts a connection or starts its run.</summary>
    public void Own() => Volatile.Write(ref _owner, Environment.CurrentManagedThreadId);

    /// <summary>
    /// No thread owns the list any more (the run ended; call after <see cref="Flush"/>): a later thread that gets the same managed
    /// id (ids of ended threads are reused) must not have its writes held, since it would never wait in a twin's wait.
    /// </summary>
    public void Disown() => Volatile.Write(ref _owner, -1);

    /// <summary>An outbox of the task's connections began to hold bytes (on the task's thread): it goes out at the next flush.</summary>
    public void Hold(TwinHeldOutbox outbox)
    {
        lock (_gate)
        {
            if (!_any)
            {
                _any = true;
                _budget = StatementBound;
                TwinWait.BeforeBlocking(_flush);
            }
            _holding.Add(outbox);
        }
    }

    /// <summary>One statement ran: the held bytes go out once <see cref="StatementBound"/> ran since the first was held.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public void Statement()
    {
        if (_any && --_budget <= 0)
        {
            Flush();
        }
    }

    /// <summary>Writes what every connection of the task holds, each in one write, in the order the task sent it.</summary>
    public void Flush()
    {
        TwinHeldOutbox[] holding;
        lock (_gate)
        {
            if (!_any)
            {
                return;
            }
            _any = false;
            holding = [.. _holding];
            _holding.Clear();
            if (OwnedByCurrentThread)
            {
                // The hook is the owner's (Hold sets it on that thread); another thread that flushes (a stop, an EKI_Close) must not
                // clear its own hook, which serves a list of its own. A hook left on the owner finds nothing held and returns.
                TwinWait.BeforeBlocking(null);
            }
        }
        foreach (TwinHeldOutbox outbox in holding)
        {
            outbox.Flush();
        }
    }
}
