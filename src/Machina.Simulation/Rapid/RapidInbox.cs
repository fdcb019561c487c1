namespace Machina.Simulation.Rapid;

/// <summary>
/// What the controller's network stack received on one connection and the program has not read yet: the controller reads the
/// socket as data arrives, and the program's SocketReceive takes up to a string's length from here. After the other end closed,
/// what arrived before stays readable; then SocketReceive reports the connection closed.
/// </summary>
internal sealed class RapidInbox
{
    // A read position into one buffer: a take copies only what it returns (Remove(0, n) moved everything still held on every
    // 80-character read, ~3 KB per action with a backlog). The held part moves to the front only when an arrival finds no room
    // at the end, and the buffer doubles when the held part fills more than half of it: each character moves O(1) times.
    private const int InitialCapacity = 1024;
    private readonly object _gate = new();
    private char[] _buffer = new char[InitialCapacity];
    private int _start;
    private int _end;
    // Continuations run on the thread that adds (outside the lock): the task's only waiter is a twin's thread blocked in TwinWait,
    // which that wakes directly; run asynchronously, each arrival woke the thread pool, whose workers spin (issue 45).
    private TaskCompletionSource _arrived = new();
    // The count the waiting SocketReceive needs (\ReadNoOfBytes): an arrival that leaves fewer held does not wake it.
    private int _awaited = 1;
    private bool _closed;

    /// <summary>How many characters (bytes) are held and not read yet.</summary>
    public int Count
    {
        get
        {
            lock (_gate)
            {
                return _end - _start;
            }
        }
    }

    /// <summary>Adds what arrived on the connection.</summary>
    public void Add(string text)
    {
        TaskCompletionSource? arrived = null;
        lock (_gate)
        {
            Append(text);
            if (_end - _start >= _awaited)
            {
                arrived = _arrived;
            }
        }
        arrived?.TrySetResult();
    }

    /// <summary>The other end closed the connection (or it broke): nothing more arrives.</summary>
    public void Close()
    {
        TaskCompletionSource arrived;
        lock (_gate)
        {
            _closed = true;
            arrived = _arrived;
        }
        arrived.TrySetResult();
    }

    /// <summary>
    /// Takes up to <paramref name="max"/> characters: the text, "" when the connection is closed and everything was read, or null
    /// when nothing is there yet (then <paramref name="arrival"/> completes when something arrives or the connection closes).
    /// </summary>
    public string? TryTake(int max, out Task arrival) => TryTake(max, 1, out arrival);

    /// <summary>
    /// Takes at least <paramref name="least"/> and up to <paramref name="max"/> characters: the text; "" when the connection is
    /// closed and fewer than <paramref name="least"/> are held (they stay: they can never make up the count); or null when fewer
    /// are held (then nothing is taken, and <paramref name="arrival"/> completes when enough arrived or the connection closes).
    /// </summary>
    public string? TryTake(int max, int least, out Task arrival)
    {
        lock (_gate)
        {
            arrival = Task.CompletedTask;
            int held = _end - _start;
            if (held >= least)
            {
                int n = Math.Min(max, held);
                string text = new(_buffer, _start, n);
                _start += n;
                if (_start == _end)
                {
                    (_start, _end) = (0, 0);
                }
                return text;
            }
            if (_closed)
            {
                return "";
            }
            if (_arrived.Task.IsCompleted)
            {
                _arrived = new();
            }
            _awaited = least;
            arrival = _arrived.Task;
            return null;
        }
    }

    private void Append(string text)
    {
        if (_end + text.Length > _buffer.Length)
        {
            int held = _end - _start;
            char[] target = held + text.Length > _buffer.Length / 2
                ? new char[Math.Max(_buffer.Length * 2, 2 * (held + text.Length))]
                : _buffer;
            Array.Copy(_buffer, _start, target, 0, held);
            (_buffer, _start, _end) = (target, 0, held);
        }
        text.CopyTo(0, _buffer, _end, text.Length);
        _end += text.Length;
    }
}
