namespace Machina.Simulation.Twin;

/// <summary>
/// How many connections one port serves at once (issue 40): a client past the limit is closed as soon as it is accepted, with
/// a line that says why, so a flood of clients costs neither threads nor memory. Thread-safe.
/// </summary>
/// <param name="limit">The most connections served at once (at least 1).</param>
internal sealed class ConnectionCap(int limit)
{
    private int _open;

    /// <summary>The most connections served at once.</summary>
    public int Limit { get; } = limit > 0 ? limit : throw new ArgumentOutOfRangeException(nameof(limit), "A port serves at least one connection.");

    /// <summary>The connections served now.</summary>
    public int Open => Volatile.Read(ref _open);

    /// <summary>True, and the connection counted, when one more may be served; false (nothing counted) at the limit.</summary>
    public bool TryEnter()
    {
        while (true)
        {
            int open = Volatile.Read(ref _open);
            if (open >= Limit)
            {
                return false;
            }
            if (Interlocked.CompareExchange(ref _open, open + 1, open) == open)
            {
                return true;
            }
        }
    }

    /// <summary>A connection counted by <see cref="TryEnter"/> ended.</summary>
    public void Leave() => Interlocked.Decrement(ref _open);

    /// <summary>The line a refused connection leaves: which port, who, and the limit.</summary>
    public string Refusal(string port, string? who) =>
        $"{port}: connection from {who ?? "a client"} refused: {Limit} connections are open, the most this port serves at once";
}
