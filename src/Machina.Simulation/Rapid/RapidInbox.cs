using System.Text;

namespace Machina.Simulation.Rapid;

/// <summary>
/// What the controller's network stack received on one connection and the program has not read yet: the controller reads the
/// socket as data arrives, and the program's SocketReceive takes up to a string's length from here. After the other end closed,
/// what arrived before stays readable; then SocketReceive reports the connection closed.
/// </summary>
internal sealed class RapidInbox
{
    private readonly object _gate = new();
    private readonly StringBuilder _text = new();
    // Continuations run on the thread that adds (outside the lock): the task's only waiter is a twin's thread blocked in TwinWait,
    // which that wakes directly; run asynchronously, each arrival woke the thread pool, whose workers spin (issue 45).
    private TaskCompletionSource _arrived = new();
    private bool _closed;

    /// <summary>Adds what arrived on the connection.</summary>
    public void Add(string text)
    {
        TaskCompletionSource arrived;
        lock (_gate)
        {
            _text.Append(text);
            arrived = _arrived;
        }
        arrived.TrySetResult();
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
    public string? TryTake(int max, out Task arrival)
    {
        lock (_gate)
        {
            arrival = Task.CompletedTask;
            if (_text.Length > 0)
            {
                int n = Math.Min(max, _text.Length);
                string text = _text.ToString(0, n);
                _text.Remove(0, n);
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
            arrival = _arrived.Task;
            return null;
        }
    }
}
