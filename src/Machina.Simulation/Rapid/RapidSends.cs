using System.Runtime.CompilerServices;

namespace Machina.Simulation.Rapid;

/// <summary>
/// The connections on which one task's socket sends are held (<see cref="RapidOutbox"/>), and when they go out: when the task is
/// about to block in any wait (<see cref="Twin.TwinWait.Blocking"/>), after <see cref="StatementBound"/> statements without
/// one, and when its run ends. Used on the task's own thread (its end may be recorded from another: the list is locked).
/// </summary>
internal sealed class RapidSends
{
    /// <summary>
    /// How many statements a task runs after its first held send before the held bytes go out without a wait: a program that
    /// sends and then computes still gets its bytes out within so many statements (the driver runs a burst of requests in far
    /// fewer, and then waits in SocketReceive).
    /// </summary>
    public const int StatementBound = 1000;

    private readonly Lock _gate = new();
    private readonly List<RapidOutbox> _holding = [];
    private readonly Action _flush;
    private bool _any;
    private int _budget;

    /// <summary>A task's list, empty.</summary>
    public RapidSends() => _flush = Flush;

    /// <summary>An outbox of the task's connections began to hold bytes (on the task's thread): it goes out at the next flush.</summary>
    public void Hold(RapidOutbox outbox)
    {
        lock (_gate)
        {
            if (!_any)
            {
                _any = true;
                _budget = StatementBound;
                Twin.TwinWait.BeforeBlocking(_flush);
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
        RapidOutbox[] holding;
        lock (_gate)
        {
            if (!_any)
            {
                return;
            }
            _any = false;
            holding = [.. _holding];
            _holding.Clear();
            Twin.TwinWait.BeforeBlocking(null);
        }
        foreach (RapidOutbox outbox in holding)
        {
            outbox.Flush();
        }
    }
}
