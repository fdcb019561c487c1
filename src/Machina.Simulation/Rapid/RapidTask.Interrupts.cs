using System.Runtime.CompilerServices;

namespace Machina.Simulation.Rapid;

/// <summary>
/// Interrupts of a task (RAPID "Interrupts"): CONNECT ties an interrupt number to a TRAP, IError orders it for controller errors of a
/// domain and type, IDelete cancels it. An ordered interrupt queues its trap; the task runs the trap between two statements.
/// </summary>
internal sealed partial class RapidTask
{
    private readonly Lock _interruptGate = new();
    private readonly Dictionary<int, RapidRoutine> _connections = [];
    private readonly List<(int Interrupt, int Domain, int Number, int Type)> _errorOrders = [];
    private readonly Queue<(RapidRoutine Trap, RapidTrapData Data)> _pending = new();
    private volatile bool _hasPending;
    private volatile bool _queued;
    private readonly List<RapidPersOrder> _persOrders = [];
    private volatile RapidPersOrder[] _persSnapshot = [];
    private RapidPersOrder[] _persChecked = [];
    private int _persWritesSeen;
    private bool _inTrap;
    private int _nextInterrupt;

    /// <summary>True once the task ordered an interrupt for controller errors (IError) that is still connected.</summary>
    public bool OrdersErrorInterrupts
    {
        get
        {
            lock (_interruptGate)
            {
                return _errorOrders.Count > 0;
            }
        }
    }

    /// <summary>The event data of the trap running now (GetTrapData), or null outside a trap.</summary>
    public RapidTrapData? CurrentTrapData { get; private set; }

    /// <summary>CONNECT: a new interrupt number for <paramref name="trap"/>.</summary>
    public int Connect(RapidRoutine trap)
    {
        lock (_interruptGate)
        {
            int number = ++_nextInterrupt;
            _connections[number] = trap;
            return number;
        }
    }

    /// <summary>IError: interrupt <paramref name="interrupt"/> for errors of <paramref name="domain"/> (0: all), number (-1: any) and type (0: all).</summary>
    public bool OrderErrorInterrupt(int interrupt, int domain, int number, int type)
    {
        lock (_interruptGate)
        {
            if (!_connections.ContainsKey(interrupt))
            {
                return false;
            }
            _errorOrders.Add((interrupt, domain, number, type));
            return true;
        }
    }

    /// <summary>
    /// IPers: interrupt <paramref name="interrupt"/> each time the persistent data <paramref name="read"/> returns changes value (checked
    /// between statements after a write of the <paramref name="watched"/> cell, and when a motion is woken: such a write of any task
    /// wakes the motion).
    /// </summary>
    public bool OrderPersInterrupt(int interrupt, Func<object> read, RapidCell? watched)
    {
        lock (_interruptGate)
        {
            if (!_connections.ContainsKey(interrupt))
            {
                return false;
            }
            if (watched is { Storage: RapidStorage.Pers })
            {
                watched.Watched = true; // before the first look: a write after it is counted
            }
            _persOrders.Add(new RapidPersOrder(interrupt, read, RapidValues.Copy(read())));
            _persSnapshot = [.. _persOrders];
            _hasPending = true;
            return true;
        }
    }

    /// <summary>
    /// Queues the traps of IPers orders whose data changed since they were last looked at. Runs before every statement, so it
    /// compares without the lock (the orders are a snapshot; only this task's thread reads and updates their last values) and
    /// takes the lock only to queue a trap.
    /// </summary>
    private void CheckPersOrders(RapidPersOrder[] orders)
    {
        foreach (RapidPersOrder order in orders)
        {
            object now = order.Read();
            if (RapidValues.AreEqual(now, order.Last))
            {
                continue;
            }
            lock (_interruptGate)
            {
                if (_connections.TryGetValue(order.Interrupt, out RapidRoutine? trap) && _persOrders.Contains(order))
                {
                    order.Last = RapidValues.Copy(now);
                    _pending.Enqueue((trap, new RapidTrapData()));
                    _queued = true;
                }
            }
        }
    }

    /// <summary>IDelete: cancels interrupt <paramref name="interrupt"/> (nothing happens for an unknown number, as for a new intnum).</summary>
    public void DeleteInterrupt(int interrupt)
    {
        lock (_interruptGate)
        {
            _connections.Remove(interrupt);
            _errorOrders.RemoveAll(o => o.Interrupt == interrupt);
            _persOrders.RemoveAll(o => o.Interrupt == interrupt);
            _persSnapshot = [.. _persOrders];
            ForgetEvents(interrupt);
        }
    }

    /// <summary>A controller error (event domain * 10000 + number, of <paramref name="type"/>): queues the traps ordered for it.</summary>
    public void PostError(int domain, int number, int type)
    {
        lock (_interruptGate)
        {
            foreach ((int interrupt, int d, int n, int t) in _errorOrders)
            {
                if ((d == 0 || d == domain) && (n < 0 || n == number) && (t == 0 || t == type))
                {
                    Enqueue(interrupt, new RapidTrapData { Domain = domain, Number = number, Kind = type });
                }
            }
        }
    }

    /// <summary><see cref="RunPendingTraps"/> as the delegate a motion serves interrupts with (<see cref="Twin.TwinArm.Serve"/>): made once, not at every move.</summary>
    public Action ServeTraps => _serveTraps ??= RunPendingTraps;

    private Action? _serveTraps;

    /// <summary>Runs the queued traps (none while a trap runs: an interrupt waits for the trap before it to end).</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public void RunPendingTraps()
    {
        // While an IPers order stands (our driver's), most statements find nothing new: that is seen here, without the call.
        if (_hasPending && !_inTrap
            && (_queued || _timerCount > 0 || Controller.PersistentWrites != _persWritesSeen || !ReferenceEquals(_persSnapshot, _persChecked)))
        {
            LookForTraps();
        }
    }

    /// <summary>The work of <see cref="RunPendingTraps"/> while an interrupt is ordered or queued (out of line: most statements skip it).</summary>
    private void LookForTraps()
    {
        // Only when persistent data were written since the last look (or the orders changed): most statements write none.
        RapidPersOrder[] orders = _persSnapshot;
        int writes = Controller.PersistentWrites;
        if (writes != _persWritesSeen || !ReferenceEquals(orders, _persChecked))
        {
            _persWritesSeen = writes;
            _persChecked = orders;
            if (orders.Length > 0)
            {
                CheckPersOrders(orders);
            }
        }
        if (_timerCount > 0)
        {
            CheckTimers();
        }
        if (_disabled)
        {
            return;
        }
        while (_queued)
        {
            (RapidRoutine Trap, RapidTrapData Data) next;
            lock (_interruptGate)
            {
                if (!_pending.TryDequeue(out next))
                {
                    _queued = false;
                    _hasPending = StillWatching();
                    return;
                }
            }
            _inTrap = true;
            CurrentTrapData = next.Data;
            try
            {
                Machine.Run(next.Trap);
            }
            finally
            {
                _inTrap = false;
                CurrentTrapData = null;
            }
        }
    }

    /// <summary>Forgets every interrupt (the program pointer moved to main).</summary>
    public void ResetInterrupts()
    {
        lock (_interruptGate)
        {
            _connections.Clear();
            _errorOrders.Clear();
            _persOrders.Clear();
            _persSnapshot = [];
            _pending.Clear();
            ForgetAllEvents();
            _queued = false;
            _hasPending = false;
        }
    }
}

/// <summary>An IPers order: the interrupt, how to read the persistent data, and the value it had when last looked at.</summary>
internal sealed class RapidPersOrder(int interrupt, Func<object> read, object last)
{
    /// <summary>The interrupt number.</summary>
    public int Interrupt { get; } = interrupt;

    /// <summary>Reads the persistent data's value now.</summary>
    public Func<object> Read { get; } = read;

    /// <summary>The value when last looked at (a copy); only the ordering task's thread reads and writes it.</summary>
    public object Last { get; set; } = last;
}
