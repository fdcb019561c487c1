using System.Globalization;
using System.Text;

namespace Machina;

/// <summary>
/// Splits the bytes of the KUKA link into complete top-level XML elements, however TCP splits or joins them (fix of bug K5:
/// the original looked at the second character of each read and counted the letter T). XML declarations, comments and
/// whitespace between elements are skipped; both <c>&lt;R ID="1"/&gt;</c> and <c>&lt;R ID="1"&gt;&lt;/R&gt;</c> are read.
/// Anything else throws <see cref="KukaProtocolException"/> carrying the received text. The bytes waiting for the end of
/// an element are bounded by <see cref="MaxElementLength"/>. Not thread-safe: one reader per socket.
/// </summary>
internal sealed class KukaXmlReader : IMessageReader<KukaElement>
{
    /// <summary>Longest element accepted (bytes); a batch of <see cref="KukaProtocol.Capacity"/> actions is about 25 KB.</summary>
    public const int MaxElementLength = 64 * 1024;

    private const int MaxDepth = 8;

    /// <summary>
    /// The names the link uses (elements and attributes of docs/protocol-kuka.md): a name read is one of these strings when it
    /// matches, so an acknowledgement's <c>R</c> and <c>ID</c> are not new strings each time.
    /// </summary>
    private static readonly string[] KnownNames =
    [
        KukaProtocol.Acknowledgement, KukaProtocol.State, KukaProtocol.Failure, KukaProtocol.Control, KukaProtocol.Pose, KukaProtocol.Action,
        KukaProtocol.Batch, KukaProtocol.Actions, KukaProtocol.MonitorRate, "ID", "V", "K", "T", "M", "Code", "Text", "VR", "Executed", "Received",
        "Model", "Ms", "X", "Y", "Z", "A", "B", "C", "A1", "A2", "A3", "A4", "A5", "A6", "V1", "V2", "V3", "V4", "V5", "V6", "V7",
    ];

    // The attributes of the element being read, until its start tag ends (then copied into an array of their number): one list for
    // every element, not one each.
    private readonly List<KeyValuePair<string, string>> _attributes = [];

    private byte[] _buffer = new byte[1024];
    private int _start;
    private int _end;

    // False inside an element after an incomplete parse, until a '>' arrives: every item ends with one, so parsing the same
    // bytes again before could not complete it (a large element trickling in was parsed again from its start for each piece;
    // its garbage is then found at the next '>' or at the length bound).
    private bool _mayComplete = true;

    /// <summary>Bytes received but not yet returned as part of a complete element.</summary>
    public int PendingByteCount => _end - _start;

    /// <summary>Adds received bytes; call <see cref="TryRead"/> until it returns false afterwards.</summary>
    public void Append(ReadOnlySpan<byte> data)
    {
        ReceiveBuffer.Append(ref _buffer, ref _start, ref _end, data);
        _mayComplete |= data.Contains((byte)'>');
    }

    /// <summary>Returns the next complete top-level element, or false when more bytes are needed.</summary>
    /// <exception cref="KukaProtocolException">The received text is not XML of the protocol.</exception>
    public bool TryRead(out KukaElement element)
    {
        while (true)
        {
            Outcome outcome = Outcome.Incomplete;
            KukaElement? parsed = null;
            var parser = new Parser(_buffer.AsSpan(_start, _end - _start), _attributes);
            if (_mayComplete)
            {
                outcome = parser.Next(out parsed);
            }
            if (outcome == Outcome.Incomplete)
            {
                _mayComplete = _end == _start;
                if (_end - _start > MaxElementLength)
                {
                    Fail($"The controller sent more than {MaxElementLength} bytes without completing an XML element: this is not the Machina KUKA driver protocol.");
                }
                element = null!;
                return false;
            }
            if (outcome == Outcome.Garbage)
            {
                Fail(parser.Error!);
            }
            _start += parser.Position;
            if (_start == _end)
            {
                _start = _end = 0;
            }
            if (outcome == Outcome.Element)
            {
                element = parsed!;
                return true;
            }
        }
    }

    private void Fail(string message)
    {
        string text = Encoding.UTF8.GetString(_buffer, _start, Math.Min(_end - _start, 200));
        _start = _end = 0;
        _mayComplete = true;
        throw new KukaProtocolException(message, text);
    }

    private enum Outcome
    {
        Element,
        Skipped,
        Incomplete,
        Garbage,
    }

    /// <summary>Parses one top-level item from the start of the pending bytes.</summary>
    private ref struct Parser(ReadOnlySpan<byte> data, List<KeyValuePair<string, string>> attributes)
    {
        private readonly ReadOnlySpan<byte> _data = data;
        private readonly List<KeyValuePair<string, string>> _attributes = attributes;

        public int Position { get; private set; }

        public string? Error { get; private set; }

        private readonly bool AtEnd => Position >= _data.Length;

        public Outcome Next(out KukaElement? element)
        {
            element = null;
            SkipWhitespace();
            if (AtEnd)
            {
                return Outcome.Incomplete;
            }
            if (_data[Position] != '<')
            {
                return Garbage("The controller sent text outside an XML element: this is not the Machina KUKA driver protocol.");
            }
            ReadOnlySpan<byte> rest = _data[Position..];
            if (rest.Length < 4 && "<!--"u8.StartsWith(rest))
            {
                return Outcome.Incomplete;
            }
            if (rest.StartsWith("<?"u8))
            {
                return SkipPast("?>"u8);
            }
            if (rest.StartsWith("<!--"u8))
            {
                return SkipPast("-->"u8);
            }
            if (rest.Length < 2)
            {
                return Outcome.Incomplete;
            }
            Outcome outcome = ReadElement(0, out element);
            return outcome;
        }

        private Outcome SkipPast(ReadOnlySpan<byte> end)
        {
            int found = _data[Position..].IndexOf(end);
            if (found < 0)
            {
                return Outcome.Incomplete;
            }
            Position += found + end.Length;
            return Outcome.Skipped;
        }

        private Outcome ReadElement(int depth, out KukaElement? element)
        {
            element = null;
            if (depth >= MaxDepth)
            {
                return Garbage($"The controller sent XML nested more than {MaxDepth} levels deep.");
            }
            Position++; // '<'
            Outcome outcome = ReadName(out string name);
            if (outcome != Outcome.Element)
            {
                return outcome;
            }
            _attributes.Clear();
            KeyValuePair<string, string>[] attributes;
            while (true)
            {
                bool spaced = SkipWhitespace();
                if (AtEnd)
                {
                    return Outcome.Incomplete;
                }
                byte c = _data[Position];
                if (c == '/')
                {
                    if (Position + 1 >= _data.Length)
                    {
                        return Outcome.Incomplete;
                    }
                    if (_data[Position + 1] != '>')
                    {
                        return Garbage($"The element <{name}> is malformed ('/' not followed by '>').");
                    }
                    Position += 2;
                    element = new KukaElement(name, _attributes.ToArray(), [], "");
                    return Outcome.Element;
                }
                if (c == '>')
                {
                    Position++;
                    attributes = _attributes.ToArray(); // the list is the children's next
                    break;
                }
                if (!spaced)
                {
                    return Garbage($"The element <{name}> is malformed (attributes must be separated by spaces).");
                }
                outcome = ReadAttribute(name, out KeyValuePair<string, string> attribute);
                if (outcome != Outcome.Element)
                {
                    return outcome;
                }
                _attributes.Add(attribute);
            }
            List<KukaElement>? children = null;
            StringBuilder? text = null;
            while (true)
            {
                if (AtEnd)
                {
                    return Outcome.Incomplete;
                }
                if (_data[Position] != '<')
                {
                    int stop = _data[Position..].IndexOf((byte)'<');
                    if (stop < 0)
                    {
                        return Outcome.Incomplete;
                    }
                    outcome = Decode(_data.Slice(Position, stop), text ??= new StringBuilder());
                    if (outcome != Outcome.Element)
                    {
                        return outcome;
                    }
                    Position += stop;
                    continue;
                }
                ReadOnlySpan<byte> rest = _data[Position..];
                if (rest.Length < 4)
                {
                    return Outcome.Incomplete;
                }
                if (rest.StartsWith("<!--"u8))
                {
                    outcome = SkipPast("-->"u8);
                    if (outcome == Outcome.Incomplete)
                    {
                        return outcome;
                    }
                    continue;
                }
                if (rest[1] == '/')
                {
                    Position += 2;
                    outcome = ReadName(out string closing);
                    if (outcome != Outcome.Element)
                    {
                        return outcome;
                    }
                    SkipWhitespace();
                    if (AtEnd)
                    {
                        return Outcome.Incomplete;
                    }
                    if (closing != name || _data[Position] != '>')
                    {
                        return Garbage($"The element <{name}> is closed by </{closing}>.");
                    }
                    Position++;
                    element = new KukaElement(name, attributes, (IReadOnlyList<KukaElement>?)children ?? [], text is null ? "" : text.ToString().Trim());
                    return Outcome.Element;
                }
                outcome = ReadElement(depth + 1, out KukaElement? child);
                if (outcome != Outcome.Element)
                {
                    return outcome;
                }
                (children ??= []).Add(child!);
            }
        }

        private Outcome ReadAttribute(string element, out KeyValuePair<string, string> attribute)
        {
            attribute = default;
            Outcome outcome = ReadName(out string name);
            if (outcome != Outcome.Element)
            {
                return outcome;
            }
            SkipWhitespace();
            if (AtEnd)
            {
                return Outcome.Incomplete;
            }
            if (_data[Position] != '=')
            {
                return Garbage($"The attribute {name} of <{element}> has no value.");
            }
            Position++;
            SkipWhitespace();
            if (AtEnd)
            {
                return Outcome.Incomplete;
            }
            byte quote = _data[Position];
            if (quote is not ((byte)'"' or (byte)'\''))
            {
                return Garbage($"The value of attribute {name} of <{element}> is not quoted.");
            }
            int length = _data[(Position + 1)..].IndexOf(quote);
            if (length < 0)
            {
                return Outcome.Incomplete;
            }
            ReadOnlySpan<byte> raw = _data.Slice(Position + 1, length);
            if (raw.IndexOf((byte)'<') >= 0)
            {
                return Garbage($"The value of attribute {name} of <{element}> contains '<'.");
            }
            string value;
            if (raw.IndexOf((byte)'&') < 0)
            {
                value = Encoding.UTF8.GetString(raw); // no entity: the text as it is (a number, mostly)
            }
            else
            {
                var decoded = new StringBuilder(raw.Length);
                outcome = Decode(raw, decoded);
                if (outcome != Outcome.Element)
                {
                    return outcome;
                }
                value = decoded.ToString();
            }
            Position += length + 2;
            attribute = new(name, value);
            return Outcome.Element;
        }

        private Outcome ReadName(out string name)
        {
            int length = 0;
            while (Position + length < _data.Length && IsNameByte(_data[Position + length]))
            {
                length++;
            }
            name = "";
            if (Position + length >= _data.Length)
            {
                return Outcome.Incomplete;
            }
            if (length == 0 || char.IsAsciiDigit((char)_data[Position]))
            {
                return Garbage("The controller sent '<' without an element name after it.");
            }
            name = Known(_data.Slice(Position, length)) ?? Encoding.ASCII.GetString(_data.Slice(Position, length));
            Position += length;
            return Outcome.Element;
        }

        /// <summary>The known name these bytes spell (<see cref="KnownNames"/>), or null.</summary>
        private static string? Known(ReadOnlySpan<byte> name)
        {
            foreach (string known in KnownNames)
            {
                if (known.Length == name.Length && Ascii.Equals(name, known))
                {
                    return known;
                }
            }
            return null;
        }

        private static bool IsNameByte(byte b) => char.IsAsciiLetterOrDigit((char)b) || b is (byte)'_' or (byte)'-' or (byte)'.' or (byte)':';

        /// <summary>Appends UTF-8 text with its entities (&amp;lt; &amp;gt; &amp;amp; &amp;quot; &amp;apos; &amp;#n; &amp;#xh;) decoded.</summary>
        private Outcome Decode(ReadOnlySpan<byte> raw, StringBuilder into)
        {
            string text = Encoding.UTF8.GetString(raw);
            int i = 0;
            while (i < text.Length)
            {
                int amp = text.IndexOf('&', i);
                if (amp < 0)
                {
                    into.Append(text, i, text.Length - i);
                    break;
                }
                into.Append(text, i, amp - i);
                int semicolon = text.IndexOf(';', amp);
                if (semicolon < 0 || semicolon - amp > 10)
                {
                    return Garbage("The controller sent an '&' that does not start an XML entity.");
                }
                string entity = text[(amp + 1)..semicolon];
                if (!TryEntity(entity, into))
                {
                    return Garbage($"The controller sent the unknown XML entity &{entity};.");
                }
                i = semicolon + 1;
            }
            return Outcome.Element;
        }

        private static bool TryEntity(string entity, StringBuilder into)
        {
            switch (entity)
            {
                case "lt":
                    into.Append('<');
                    return true;
                case "gt":
                    into.Append('>');
                    return true;
                case "amp":
                    into.Append('&');
                    return true;
                case "quot":
                    into.Append('"');
                    return true;
                case "apos":
                    into.Append('\'');
                    return true;
            }
            bool hex = entity.StartsWith("#x", StringComparison.OrdinalIgnoreCase);
            if ((hex || entity.StartsWith('#'))
                && int.TryParse(entity.AsSpan(hex ? 2 : 1), hex ? NumberStyles.AllowHexSpecifier : NumberStyles.None, CultureInfo.InvariantCulture, out int code)
                && code is > 0 and <= 0x10FFFF && code is < 0xD800 or > 0xDFFF)
            {
                into.Append(char.ConvertFromUtf32(code));
                return true;
            }
            return false;
        }

        private bool SkipWhitespace()
        {
            int before = Position;
            while (!AtEnd && _data[Position] is (byte)' ' or (byte)'\t' or (byte)'\r' or (byte)'\n' or 0)
            {
                Position++;
            }
            return Position > before;
        }

        private Outcome Garbage(string error)
        {
            Error = error;
            return Outcome.Garbage;
        }
    }
}
