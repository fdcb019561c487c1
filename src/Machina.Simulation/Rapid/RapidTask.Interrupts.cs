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
    private readonly List<(int Interrupt, Func<object> Read, object Last)> _persOrders = [];
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
    /// between statements and when a motion is woken: a PERS write of any task wakes the motion).
    /// </summary>
    public bool OrderPersInterrupt(int interrupt, Func<object> read)
    {
        lock (_interruptGate)
        {
            if (!_connections.ContainsKey(interrupt))
            {
                return false;
            }
            _persOrders.Add((interrupt, read, RapidValues.Copy(read())));
            _hasPending = true;
            Controller.WatchesPersistents = true;
            return true;
        }
    }

    /// <summary>Queues the traps of IPers orders whose data changed since they were last looked at.</summary>
    private void CheckPersOrders()
    {
        lock (_interruptGate)
        {
            for (int i = 0; i < _persOrders.Count; i++)
            {
                (int interrupt, Func<object> read, object last) = _persOrders[i];
                object now = read();
                if (!RapidValues.AreEqual(now, last) && _connections.TryGetValue(interrupt, out RapidRoutine? trap))
                {
                    _persOrders[i] = (interrupt, read, RapidValues.Copy(now));
                    _pending.Enqueue((trap, new RapidTrapData()));
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
        }
    }

    /// <summary>A controller error (event domain * 10000 + number, of <paramref name="type"/>): queues the traps ordered for it.</summary>
    public void PostError(int domain, int number, int type)
    {
        lock (_interruptGate)
        {
            foreach ((int interrupt, int d, int n, int t) in _errorOrders)
            {
                if ((d == 0 || d == domain) && (n < 0 || n == number) && (t == 0 || t == type) && _connections.TryGetValue(interrupt, out RapidRoutine? trap))
                {
                    _pending.Enqueue((trap, new RapidTrapData { Domain = domain, Number = number, Kind = type }));
                    _hasPending = true;
                }
            }
        }
    }

    /// <summary>Runs the queued traps (none while a trap runs: an interrupt waits for the trap before it to end).</summary>
    public void RunPendingTraps()
    {
        if (!_hasPending || _inTrap)
        {
            return;
        }
        if (_persOrders.Count > 0)
        {
            CheckPersOrders();
        }
        while (true)
        {
            (RapidRoutine Trap, RapidTrapData Data) next;
            lock (_interruptGate)
            {
                if (!_pending.TryDequeue(out next))
                {
                    _hasPending = _persOrders.Count > 0;
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
            _pending.Clear();
            _hasPending = false;
        }
    }
}
