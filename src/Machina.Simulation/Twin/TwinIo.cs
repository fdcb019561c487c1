namespace Machina.Simulation.Twin;

/// <summary>
/// The controller's inputs, outputs and fieldbus registers (a controller has a fixed number of each), and the signal a program
/// waiting on them sleeps on (<see cref="WaitForChange"/>): the one IO model of the three interpreters (URScript's banks, RAPID's
/// signals, KRL's <c>$IN</c>, <c>$OUT</c>, <c>$ANIN</c>, <c>$ANOUT</c>), which the host sets and reads the same way for each brand.
/// </summary>
internal sealed class TwinIo
{
    private readonly Lock _gate = new();
    private readonly object _changed = new();
    private long _version;
    private long _writes;
    private readonly Dictionary<string, bool[]> _bits = new(StringComparer.Ordinal);
    private readonly Dictionary<string, double[]> _numbers = new(StringComparer.Ordinal);

    /// <summary>Declares a bank of digital signals (all false).</summary>
    public void AddBits(string bank, int count)
    {
        lock (_gate)
        {
            _bits[bank] = new bool[count];
            Wrote();
        }
    }

    /// <summary>Declares a bank of numeric signals or registers (all 0).</summary>
    public void AddNumbers(string bank, int count)
    {
        lock (_gate)
        {
            _numbers[bank] = new double[count];
            Wrote();
        }
    }

    /// <summary>
    /// How many times a signal or register was written (or a bank declared), whatever its value: a reader that shows the outputs
    /// (<c>machina sim</c>'s activity) reads them again only when this moved. An atomic read, without the lock.
    /// </summary>
    public long Writes => Volatile.Read(ref _writes);

    /// <summary>Told of every write (the controller's, for <c>machina sim</c>'s activity that shows the outputs), or null.</summary>
    public TwinChangeSignal? Changes { get; set; }

    /// <summary>Counts a write (under the lock: one writer at a time) and tells <see cref="Changes"/>.</summary>
    private void Wrote()
    {
        Volatile.Write(ref _writes, _writes + 1);
        Changes?.Changed();
    }

    /// <summary>How many signals a bank has (0 when there is no such bank).</summary>
    public int Count(string bank) => _bits.TryGetValue(bank, out bool[]? b) ? b.Length : _numbers.TryGetValue(bank, out double[]? n) ? n.Length : 0;

    /// <summary>Reads a digital signal.</summary>
    public bool GetBit(string bank, int index)
    {
        lock (_gate)
        {
            return _bits[bank][index];
        }
    }

    /// <summary>Writes a digital signal.</summary>
    public void SetBit(string bank, int index, bool value)
    {
        lock (_gate)
        {
            _bits[bank][index] = value;
            Wrote();
        }
    }

    /// <summary>Copies a bank of digital signals into <paramref name="into"/> (as many as it holds), under one lock.</summary>
    public void ReadBits(string bank, Span<bool> into)
    {
        lock (_gate)
        {
            _bits[bank].AsSpan(0, into.Length).CopyTo(into);
        }
    }

    /// <summary>Copies a bank of numeric signals or registers into <paramref name="into"/> (as many as it holds), under one lock.</summary>
    public void ReadNumbers(string bank, Span<double> into)
    {
        lock (_gate)
        {
            _numbers[bank].AsSpan(0, into.Length).CopyTo(into);
        }
    }

    /// <summary>Reads a numeric signal or register.</summary>
    public double GetNumber(string bank, int index)
    {
        lock (_gate)
        {
            return _numbers[bank][index];
        }
    }

    /// <summary>Writes a numeric signal or register.</summary>
    public void SetNumber(string bank, int index, double value)
    {
        lock (_gate)
        {
            _numbers[bank][index] = value;
            Wrote();
        }
    }

    /// <summary>
    /// How many times an input, a flag or a channel changed (a waiting program reads it before it looks at its condition). A
    /// volatile read: atomic on every platform (64-bit reads are; 32-bit ones go through an interlocked exchange) and an acquire,
    /// so what the program looks at after it is not read before it; <see cref="Changed"/> writes it with a release after the
    /// change. An interlocked read (a locked compare-exchange on x64) cost a bus-locked instruction per KRL statement.
    /// </summary>
    public long Version => Volatile.Read(ref _version);

    /// <summary>Counts a change of what programs wait on and wakes every program waiting in <see cref="WaitForChange"/>.</summary>
    public void Changed()
    {
        lock (_changed)
        {
            Volatile.Write(ref _version, _version + 1); // one writer at a time (the lock); readers read it without the lock
            Monitor.PulseAll(_changed);
        }
    }

    /// <summary>
    /// Blocks until <see cref="Version"/> is no longer <paramref name="version"/> or <paramref name="timeout"/> passed; true when it
    /// changed. The thread sleeps in the kernel from the start: a semaphore's or a task's wait spins first, and a twin woken by every
    /// streamed action spent more processor time spinning than running the action (issue 45). Throws
    /// <see cref="OperationCanceledException"/> when <paramref name="cancellation"/> ends the wait first.
    /// </summary>
    public bool WaitForChange(long version, TimeSpan timeout, CancellationToken cancellation)
    {
        cancellation.ThrowIfCancellationRequested();
        if (Version != version)
        {
            return true;
        }
        TwinWait.Blocking();
        using CancellationTokenRegistration wake = cancellation.Register(static o =>
        {
            lock (o!)
            {
                Monitor.PulseAll(o);
            }
        }, _changed);
        long deadline = Environment.TickCount64 + (long)timeout.TotalMilliseconds;
        lock (_changed)
        {
            while (_version == version)
            {
                cancellation.ThrowIfCancellationRequested();
                long left = deadline - Environment.TickCount64;
                if (left <= 0 || !Monitor.Wait(_changed, (int)Math.Min(left, int.MaxValue)))
                {
                    return _version != version;
                }
            }
        }
        return true;
    }
}
