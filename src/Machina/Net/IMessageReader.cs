namespace Machina;

/// <summary>
/// Splits the bytes of one connection into a protocol's messages, however TCP chunks them. Bounded: a stream that is not the
/// protocol throws a <see cref="MachinaException"/> (carrying what was received) instead of growing memory. Not thread-safe:
/// one reader per connection, used by its receive loop.
/// </summary>
/// <typeparam name="TMessage">One complete message of the protocol.</typeparam>
internal interface IMessageReader<TMessage>
{
    /// <summary>Adds received bytes; call <see cref="TryRead"/> until it returns false afterwards.</summary>
    void Append(ReadOnlySpan<byte> data);

    /// <summary>Returns the next complete message, or false when more bytes are needed.</summary>
    /// <exception cref="MachinaException">The received bytes are not a message of the protocol.</exception>
    bool TryRead(out TMessage message);
}
