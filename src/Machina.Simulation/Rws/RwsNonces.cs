namespace Machina.Simulation.Rws;

/// <summary>
/// The digest nonces the server handed out (RFC 7616 §3.3, §5.5): each lives <see cref="Lifetime"/>, and each answer that uses
/// one must count up (<c>nc</c> greater than the last one taken), so a header seen on the wire cannot be sent again. At most
/// <see cref="Capacity"/> are kept; a new one pushes out the oldest. Not thread-safe: the server calls it under its lock.
/// </summary>
internal sealed class RwsNonces(TimeProvider time)
{
    private readonly Dictionary<string, Entry> _nonces = new(StringComparer.Ordinal);
    private readonly Queue<string> _order = new();

    /// <summary>How long a nonce is taken after it was handed out (default 5 minutes).</summary>
    public TimeSpan Lifetime { get; set; } = TimeSpan.FromMinutes(5);

    /// <summary>Most nonces kept at once.</summary>
    public const int Capacity = 1024;

    /// <summary>Hands out a fresh nonce.</summary>
    public string Issue()
    {
        while (_order.Count >= Capacity)
        {
            _nonces.Remove(_order.Dequeue());
        }
        string nonce = RwsDigest.NewNonce();
        _nonces[nonce] = new Entry(time.GetTimestamp(), 0);
        _order.Enqueue(nonce);
        return nonce;
    }

    /// <summary>
    /// Takes <paramref name="nonce"/> with the count <paramref name="count"/> (hexadecimal, as <c>nc</c> is sent): Fresh when it
    /// was handed out, has not expired and the count is greater than any taken before with it; Stale when it expired; else Unknown.
    /// </summary>
    public RwsNonceState Take(string nonce, string? count)
    {
        if (!_nonces.TryGetValue(nonce, out Entry entry))
        {
            return RwsNonceState.Unknown;
        }
        if (time.GetElapsedTime(entry.Issued) > Lifetime)
        {
            _nonces.Remove(nonce);
            return RwsNonceState.Stale;
        }
        if (count is null || count.Length != 8 || !long.TryParse(count, System.Globalization.NumberStyles.AllowHexSpecifier,
                System.Globalization.CultureInfo.InvariantCulture, out long nc) || nc <= entry.Count)
        {
            return RwsNonceState.Unknown;
        }
        _nonces[nonce] = entry with { Count = nc };
        return RwsNonceState.Fresh;
    }

    private readonly record struct Entry(long Issued, long Count);
}

/// <summary>What a digest answer's nonce is worth.</summary>
internal enum RwsNonceState
{
    /// <summary>Not handed out, no longer kept, or a count not greater than the last: a replay.</summary>
    Unknown,

    /// <summary>Handed out and expired: the client is told <c>stale=TRUE</c> and asks again with the new nonce.</summary>
    Stale,

    /// <summary>Handed out, alive, counted up.</summary>
    Fresh,
}
