using System.Globalization;
using System.Text;

namespace Machina;

/// <summary>
/// Splits the bytes received from the ABB driver or monitor into messages, however TCP chunks them.
/// Messages end with <c>;</c>; a <c>&gt;</c> joins continuation chunks and reads as a space (spec online §6.2).
/// Numbers are parsed with the invariant culture (fix of bug A7). Garbage throws <see cref="AbbProtocolException"/>
/// carrying the received text. Not thread-safe: one reader per socket, used by its receive loop.
/// </summary>
internal sealed class AbbMessageReader : IMessageReader<AbbMessage>
{
    /// <summary>Longest message accepted before the stream is declared garbage (the longest real one, <c>$24</c>, is about 250 bytes).</summary>
    public const int MaxMessageLength = 4096;

    private byte[] _buffer = new byte[1024];
    private int _start;
    private int _end;
    private int _scanned;

    /// <summary>Bytes received but not yet returned as a complete message.</summary>
    public int PendingByteCount => _end - _start;

    /// <summary>Adds received bytes; call <see cref="TryRead"/> until it returns false afterwards.</summary>
    public void Append(ReadOnlySpan<byte> data) => _scanned -= ReceiveBuffer.Append(ref _buffer, ref _start, ref _end, data);

    /// <summary>Returns the next complete message, or false when more bytes are needed. Empty messages are skipped.</summary>
    /// <exception cref="AbbProtocolException">The received text is not a message of the protocol.</exception>
    public bool TryRead(out AbbMessage message)
    {
        while (true)
        {
            int found = _buffer.AsSpan(_scanned, _end - _scanned).IndexOf((byte)';');
            if (found < 0)
            {
                _scanned = _end;
                if (_end - _start > MaxMessageLength)
                {
                    string text = Encoding.UTF8.GetString(_buffer, _start, Math.Min(_end - _start, 200));
                    Reset();
                    throw new AbbProtocolException(
                        $"The controller sent more than {MaxMessageLength} bytes without a ';': this is not the Machina ABB driver protocol.", text);
                }
                message = default;
                return false;
            }
            int terminator = _scanned + found;
            var body = _buffer.AsSpan(_start, terminator - _start);
            _start = terminator + 1;
            _scanned = _start;
            if (_start == _end)
            {
                _start = _end = _scanned = 0;
            }
            body = body.Trim(" \t\r\n>"u8);
            if (body.IsEmpty)
            {
                continue;
            }
            message = Parse(body);
            return true;
        }
    }

    /// <summary>Forgets any partial message (after a reconnect).</summary>
    public void Reset() => _start = _end = _scanned = 0;

    /// <summary>Parses one message without its terminating <c>;</c>.</summary>
    internal static AbbMessage Parse(ReadOnlySpan<byte> body)
    {
        var tokens = new Tokenizer(body);
        byte first = body[0];
        if (first == (byte)'@')
        {
            tokens.Skip(1);
            int id = ReadInt(ref tokens, body, "id");
            if (id < 0)
            {
                throw Garbage("The controller acknowledged a negative id, which no request carries", body);
            }
            int code = tokens.AtEnd ? 0 : ReadInt(ref tokens, body, "instruction code");
            return EndOfAcknowledgement(ref tokens, body, AbbMessage.Acknowledgement(id, code));
        }
        if (first is (byte)'-' or (>= (byte)'0' and <= (byte)'9'))
        {
            return EndOfAcknowledgement(ref tokens, body, AbbMessage.Acknowledgement(0, ReadInt(ref tokens, body, "instruction code")));
        }
        if (first != (byte)'$')
        {
            throw Garbage("The controller sent a message that is neither an acknowledgement ('@') nor data ('$')", body);
        }
        tokens.Skip(1);
        if (body.Length > 1 && body[1] == (byte)'@')
        {
            tokens.Skip(1);
            int infoId = ReadInt(ref tokens, body, "id");
            int infoCode = ReadInt(ref tokens, body, "code");
            return AbbMessage.Information(infoId, infoCode, Encoding.UTF8.GetString(tokens.Rest).Replace('>', ' ').Trim());
        }
        int dataCode = ReadInt(ref tokens, body, "response code");
        var values = new double[tokens.CountRemaining()];
        for (int i = 0; i < values.Length; i++)
        {
            var token = tokens.Next();
            if (!double.TryParse(token, NumberStyles.Float, CultureInfo.InvariantCulture, out values[i]) || !double.IsFinite(values[i]))
            {
                throw Garbage($"The controller sent a ${dataCode} message with \"{Encoding.UTF8.GetString(token)}\" where a number was expected", body);
            }
        }
        return AbbMessage.Data(dataCode, values);
    }

    /// <summary>An acknowledgement ends after its code (spec online §6.2): anything more is not the protocol.</summary>
    private static AbbMessage EndOfAcknowledgement(ref Tokenizer tokens, ReadOnlySpan<byte> body, AbbMessage acknowledgement) =>
        tokens.AtEnd ? acknowledgement : throw Garbage("The controller sent an acknowledgement with more after its instruction code", body);

    private static int ReadInt(ref Tokenizer tokens, ReadOnlySpan<byte> body, string what)
    {
        var token = tokens.Next();
        if (token.IsEmpty || !TryParseInt(token, out int value))
        {
            throw Garbage($"The controller sent a message whose {what} is not a whole number", body);
        }
        return value;
    }

    /// <summary>
    /// A whole number with an optional sign, as <c>int.TryParse</c> with the invariant culture reads it: an id or a code of at
    /// most nine digits (every acknowledgement's) is read here, anything else by <c>int.TryParse</c>, which looked the culture's
    /// number format up for every token (one per acknowledgement on the link's thread).
    /// </summary>
    internal static bool TryParseInt(ReadOnlySpan<byte> token, out int value)
    {
        if (token.Length is > 0 and <= 9)
        {
            int digits = 0;
            foreach (byte b in token)
            {
                uint digit = (uint)(b - '0');
                if (digit > 9)
                {
                    return int.TryParse(token, NumberStyles.AllowLeadingSign, CultureInfo.InvariantCulture, out value);
                }
                digits = (digits * 10) + (int)digit;
            }
            value = digits;
            return true;
        }
        return int.TryParse(token, NumberStyles.AllowLeadingSign, CultureInfo.InvariantCulture, out value);
    }

    private static AbbProtocolException Garbage(string what, ReadOnlySpan<byte> body)
    {
        string text = Encoding.UTF8.GetString(body) + ";";
        return new AbbProtocolException($"{what}: \"{text}\".", text);
    }

    /// <summary>Splits a message into tokens separated by spaces, tabs, line breaks or '>'.</summary>
    private ref struct Tokenizer(ReadOnlySpan<byte> text)
    {
        private static ReadOnlySpan<byte> Separators => " \t\r\n>"u8;

        private ReadOnlySpan<byte> _rest = text;

        public readonly bool AtEnd => _rest.TrimStart(Separators).IsEmpty;

        public readonly ReadOnlySpan<byte> Rest => _rest;

        public void Skip(int count) => _rest = _rest[count..];

        public ReadOnlySpan<byte> Next()
        {
            _rest = _rest.TrimStart(Separators);
            int end = _rest.IndexOfAny(Separators);
            if (end < 0)
            {
                end = _rest.Length;
            }
            var token = _rest[..end];
            _rest = _rest[end..];
            return token;
        }

        public readonly int CountRemaining()
        {
            var copy = this;
            int count = 0;
            while (!copy.Next().IsEmpty)
            {
                count++;
            }
            return count;
        }
    }
}
