namespace Machina.Simulation.Rapid;

/// <summary>
/// Timer and signal interrupts of a task (RAPID "Interrupts": ITimer, ISignalDI, ISignalDO, ISleep, IWatch, IDisable, IEnable). A timer
/// is due on the task's clock (the wall clock, or the program time of a motion task that runs without real time); a signal order
/// queues its trap when the signal changes to its trigger value. Queued traps run between statements and during waits.
/// </summary>
internal sealed partial class RapidTask
{
    private readonly List<RapidTimerOrder> _timerOrders = [];
    private readonly List<RapidSignalOrder> _signalOrders = [];
    private readonly HashSet<int> _sleeping = [];
    private volatile bool _disabled;
    private volatile int _timerCount;
    private long _epoch = -1;

    /// <summary>True while the task has a timer or signal interrupt ordered: its waits then serve traps as they come.</summary>
    public bool HasEventOrders
    {
        get
        {
            lock (_interruptGate)
            {
                return _timerOrders.Count + _signalOrders.Count > 0;
            }
        }
    }

    /// <summary>The task's clock for timers, in seconds: the program time of a motion task without real time, the wall clock otherwise.</summary>
    private double Now()
    {
        if (IsMotionTask && !Controller.Clock.RealTime)
        {
            return Controller.Clock.Seconds;
        }
        TimeProvider time = Controller.Options.Time;
        if (_epoch < 0)
        {
            _epoch = time.GetTimestamp();
        }
        return time.GetElapsedTime(_epoch).TotalSeconds;
    }

    /// <summary>ITimer: interrupt <paramref name="interrupt"/> every <paramref name="seconds"/> (once with <paramref name="single"/>).</summary>
    public bool OrderTimer(int interrupt, double seconds, bool single)
    {
        double now = Now();
        lock (_interruptGate)
        {
            if (!_connections.ContainsKey(interrupt))
            {
                return false;
            }
            _timerOrders.Add(new RapidTimerOrder(interrupt, seconds, single, now + seconds));
            _timerCount = _timerOrders.Count;
            _hasPending = true;
            return true;
        }
    }

    /// <summary>ISignalDI/ISignalDO: interrupt <paramref name="interrupt"/> when signal (bank, index) changes to <paramref name="trigger"/> (0, 1, or 2 for both).</summary>
    public bool OrderSignal(int interrupt, string bank, int index, int trigger, bool single)
    {
        lock (_interruptGate)
        {
            if (!_connections.ContainsKey(interrupt))
            {
                return false;
            }
            _signalOrders.Add(new RapidSignalOrder(interrupt, bank, index, trigger, single));
            return true;
        }
    }

    /// <summary>ISleep (true) or IWatch (false): while asleep, the interrupt's events are dropped.</summary>
    public bool Sleep(int interrupt, bool asleep)
    {
        lock (_interruptGate)
        {
            if (!_connections.ContainsKey(interrupt))
            {
                return false;
            }
            if (asleep)
            {
                _sleeping.Add(interrupt);
            }
            else
            {
                _sleeping.Remove(interrupt);
            }
            return true;
        }
    }

    /// <summary>IDisable (true) or IEnable (false): while disabled, traps wait in the queue and run once enabled again.</summary>
    public void Disable(bool disabled) => _disabled = disabled;

    /// <summary>A signal changed to <paramref name="value"/>: queues the traps of the orders it triggers.</summary>
    public void PostSignal(string bank, int index, bool value)
    {
        lock (_interruptGate)
        {
            // In the order they were ordered; a \Single order ends with its first interrupt.
            _signalOrders.RemoveAll(order =>
            {
                if (order.Bank != bank || order.Index != index || (order.Trigger != 2 && order.Trigger == 1 != value))
                {
                    return false;
                }
                Enqueue(order.Interrupt, new RapidTrapData());
                return order.Single;
            });
        }
    }

    /// <summary>An event of the program's own (a TriggInt's point of the path): queues the trap of <paramref name="interrupt"/> unless it sleeps.</summary>
    public void PostInterrupt(int interrupt)
    {
        lock (_interruptGate)
        {
            Enqueue(interrupt, new RapidTrapData());
        }
    }

    /// <summary>Queues the trap of <paramref name="interrupt"/> unless it sleeps (call under the interrupt lock).</summary>
    private void Enqueue(int interrupt, RapidTrapData data)
    {
        if (_sleeping.Contains(interrupt) || !_connections.TryGetValue(interrupt, out RapidRoutine? trap))
        {
            return;
        }
        _pending.Enqueue((trap, data));
        _queued = true;
        _hasPending = true;
    }

    /// <summary>Queues the traps of the timers that are due (one per timer, however many periods went by).</summary>
    private void CheckTimers()
    {
        double now = Now();
        lock (_interruptGate)
        {
            // In the order they were ordered; a \Single timer ends with its interrupt.
            _timerOrders.RemoveAll(order =>
            {
                if (now < order.Due)
                {
                    return false;
                }
                Enqueue(order.Interrupt, new RapidTrapData());
                order.Due = Math.Max(order.Due + order.Period, now);
                return order.Single;
            });
            _timerCount = _timerOrders.Count;
        }
    }

    /// <summary>The seconds until the next timer is due, at most <paramref name="most"/> (how long a wait may sleep before it serves traps).</summary>
    public double NextTimerWithin(double most)
    {
        double now = Now();
        lock (_interruptGate)
        {
            foreach (RapidTimerOrder order in _timerOrders)
            {
                most = Math.Min(most, Math.Max(order.Due - now, 1e-6)); // a due time a tick away (rounding) still ends the slice there
            }
        }
        return most;
    }

    /// <summary>Drops the timer, signal and sleep state of <paramref name="interrupt"/> (IDelete; call under the interrupt lock).</summary>
    private void ForgetEvents(int interrupt)
    {
        _timerOrders.RemoveAll(o => o.Interrupt == interrupt);
        _timerCount = _timerOrders.Count;
        _signalOrders.RemoveAll(o => o.Interrupt == interrupt);
        _sleeping.Remove(interrupt);
    }

    /// <summary>Drops every timer, signal and sleep order (call under the interrupt lock).</summary>
    private void ForgetAllEvents()
    {
        _timerOrders.Clear();
        _timerCount = 0;
        _signalOrders.Clear();
        _sleeping.Clear();
        _disabled = false;
    }

    /// <summary>True while traps stay queued for later: something is still ordered that needs looking at between statements.</summary>
    private bool StillWatching() => _persOrders.Count > 0 || _timerOrders.Count > 0;
}

/// <summary>An ITimer order: the interrupt, its period (s), whether it fires once, and when it is next due on the task's clock.</summary>
internal sealed class RapidTimerOrder(int interrupt, double period, bool single, double due)
{
    /// <summary>The interrupt number.</summary>
    public int Interrupt { get; } = interrupt;

    /// <summary>The period in seconds.</summary>
    public double Period { get; } = period;

    /// <summary>True for \Single: the order ends after its first interrupt.</summary>
    public bool Single { get; } = single;

    /// <summary>When the next interrupt is due (seconds on the task's clock).</summary>
    public double Due { get; set; } = due;
}

/// <summary>An ISignalDI/ISignalDO order: the interrupt, the signal's bank and index, the trigger value (0, 1; 2 for both) and \Single.</summary>
internal sealed record RapidSignalOrder(int Interrupt, string Bank, int Index, int Trigger, bool Single);
