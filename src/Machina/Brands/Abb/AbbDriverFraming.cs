namespace Machina;

/// <summary>
/// Cuts the bytes the RAPID driver sends into messages: each ends with ';', a long one may come in chunks that end with
/// '>' (read as a space). Keeps an unfinished message for the next read; allocation-free once its buffer has grown.
/// </summary>
internal sealed class AbbDriverFraming
{
    /// <summary>Longest message accepted; anything longer is not Machina's protocol.</summary>
    internal const int MaxMessageLength = 4096;

    private byte[] _message = new byte[256];
    private int _length;

    /// <summary>Feeds received bytes; calls <paramref name="onMessage"/> with each complete message (without the ';', trimmed).</summary>
    /// <returns>False when a message grew beyond <see cref="MaxMessageLength"/> (the caller should treat it as garbage).</returns>
    internal bool Feed<TState>(ReadOnlySpan<byte> data, TState state, MessageHandler<TState> onMessage)
    {
        foreach (byte b in data)
        {
            if (b == (byte)';')
            {
                ReadOnlySpan<byte> message = _message.AsSpan(0, _length).Trim((byte)' ');
                _length = 0;
                if (!message.IsEmpty && !onMessage(state, message))
                {
                    return true;
                }
                continue;
            }
            if (_length == MaxMessageLength)
            {
                return false;
            }
            if (_length == _message.Length)
            {
                Array.Resize(ref _message, Math.Min(_message.Length * 2, MaxMessageLength));
            }
            _message[_length++] = b is (byte)'>' or (byte)'\r' or (byte)'\n' or (byte)'\t' ? (byte)' ' : b;
        }
        return true;
    }

    /// <summary>Handles one message; return false to stop reading the current data.</summary>
    internal delegate bool MessageHandler<TState>(TState state, ReadOnlySpan<byte> message);
}
