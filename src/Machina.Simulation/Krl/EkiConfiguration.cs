using System.Globalization;
using System.Xml.Linq;

namespace Machina.Simulation.Krl;

/// <summary>A value memory of an EthernetKRL channel: the tag of an element or attribute received, its type and the flag it sets.</summary>
/// <param name="Tag">The XML path, e.g. <c>DT/DR/A/@ID</c> (an attribute) or <c>DT</c> (an element).</param>
/// <param name="Type">INT, REAL, BOOL or STRING (null for an element that only sets a flag).</param>
/// <param name="SetFlag">The $FLAG set when the element has been received (0: none).</param>
internal sealed record EkiReceiveElement(string Tag, string? Type, int SetFlag);

/// <summary>
/// The binary element of a channel in raw mode (<c>&lt;RAW&gt;&lt;ELEMENT Tag="Buffer" Type="BYTE" Size="10" /&gt;&lt;/RAW&gt;</c>): a record
/// of exactly <paramref name="Size"/> bytes (BYTE), or of at most that many ending with an end string (STREAM, <c>EOS="65,66"</c>,
/// alternatives separated by <c>|</c>).
/// </summary>
/// <param name="Tag">The element's name (the memory EKI_GetString reads).</param>
/// <param name="Stream">True for STREAM, false for BYTE.</param>
/// <param name="Size">BYTE: the record's size; STREAM: its largest size (1 to 3600 bytes, the manual's range).</param>
/// <param name="EndStrings">STREAM: the end strings (each 1 to 32 bytes).</param>
/// <param name="SetFlag">The $FLAG set when a record has been received (0: none).</param>
internal sealed record EkiRawElement(string Tag, bool Stream, int Size, IReadOnlyList<byte[]> EndStrings, int SetFlag);

/// <summary>
/// An EthernetKRL channel's XML configuration as the manual describes it: the external system's role (<c>Client</c>: the robot
/// listens), address and port, the value memories' mode and limit, the ALIVE flag, and the RECEIVE and SEND elements.
/// </summary>
internal sealed class EkiConfiguration
{
    /// <summary>True when the external system is the client, so the robot controller is the server and listens.</summary>
    public bool RobotIsServer { get; private init; }

    /// <summary>The port.</summary>
    public int Port { get; private init; }

    /// <summary>True for PROTOCOL UDP (datagrams, one document each); false for TCP, the default.</summary>
    public bool Udp { get; private init; }

    /// <summary>The IP address of the configuration (the robot's own when it listens; the server's when the robot is the client).</summary>
    public string Address { get; private init; } = "127.0.0.1";

    /// <summary>FIFO (first in, first out) or LIFO memories.</summary>
    public bool Fifo { get; private init; } = true;

    /// <summary>Most elements one memory holds; more closes the connection.</summary>
    public int Limit { get; private init; } = 16;

    /// <summary>
    /// BUFFSIZE Limit: the most bytes received without being interpreted (1 to 65534, default 16384, as the manual gives them); on
    /// the twin, the longest document (top-level element) a client may send; more closes the connection.
    /// </summary>
    public int BufferSize { get; private init; } = DefaultBufferSize;

    /// <summary>The manual's default BUFFSIZE Limit.</summary>
    public const int DefaultBufferSize = 16384;

    /// <summary>The $FLAG that is TRUE while the connection is open (0: none).</summary>
    public int AliveFlag { get; private init; }

    /// <summary>The elements received, each a memory.</summary>
    public IReadOnlyList<EkiReceiveElement> Receive { get; private init; } = [];

    /// <summary>The tags that can be sent, in order.</summary>
    public IReadOnlyList<string> Send { get; private init; } = [];

    /// <summary>The binary element received (RECEIVE in raw mode), or null for XML.</summary>
    public EkiRawElement? RawReceive { get; private init; }

    /// <summary>The binary element sent (SEND in raw mode), or null for XML.</summary>
    public EkiRawElement? RawSend { get; private init; }

    /// <summary>Reads a configuration; throws <see cref="FormatException"/> with the reason for one the package would refuse.</summary>
    public static EkiConfiguration Parse(string name, string xml)
    {
        XElement root;
        try
        {
            root = XElement.Parse(xml);
        }
        catch (System.Xml.XmlException ex)
        {
            throw new FormatException($"the configuration {name}.xml is not well-formed XML: {ex.Message}");
        }
        XElement? configuration = root.Element("CONFIGURATION");
        XElement? external = configuration?.Element("EXTERNAL");
        XElement? intern = configuration?.Element("INTERNAL");
        if (root.Name != "ETHERNETKRL" || external is null || intern is null)
        {
            throw new FormatException($"the configuration {name}.xml needs <ETHERNETKRL><CONFIGURATION><EXTERNAL> and <INTERNAL>");
        }
        string type = (string?)external.Element("TYPE") ?? "Client";
        string? portText = (string?)intern.Element("PORT") ?? (string?)external.Element("PORT");
        if (!int.TryParse(portText, NumberStyles.None, CultureInfo.InvariantCulture, out int port) || port > 65534)
        {
            throw new FormatException($"the configuration {name}.xml has no valid PORT (\"{portText}\")");
        }
        XElement? buffering = intern.Element("BUFFERING");
        string protocol = ((string?)intern.Element("PROTOCOL") ?? (string?)external.Element("PROTOCOL") ?? "TCP").Trim();
        if (!string.Equals(protocol, "TCP", StringComparison.OrdinalIgnoreCase) && !string.Equals(protocol, "UDP", StringComparison.OrdinalIgnoreCase))
        {
            throw new FormatException($"the configuration {name}.xml has PROTOCOL \"{protocol}\": EthernetKRL speaks TCP or UDP");
        }
        EkiRawElement? rawReceive = Raw(name, root.Element("RECEIVE")), rawSend = Raw(name, root.Element("SEND"));
        return new EkiConfiguration
        {
            RobotIsServer = string.Equals(type, "Client", StringComparison.OrdinalIgnoreCase),
            Port = port,
            Udp = string.Equals(protocol, "UDP", StringComparison.OrdinalIgnoreCase),
            Address = ((string?)intern.Element("IP") ?? (string?)external.Element("IP") ?? "127.0.0.1").Trim(),
            Fifo = !string.Equals((string?)buffering?.Attribute("Mode"), "LIFO", StringComparison.OrdinalIgnoreCase),
            Limit = int.TryParse((string?)buffering?.Attribute("Limit"), CultureInfo.InvariantCulture, out int limit) ? Math.Clamp(limit, 1, 512) : 16,
            BufferSize = int.TryParse((string?)intern.Element("BUFFSIZE")?.Attribute("Limit"), CultureInfo.InvariantCulture, out int size)
                ? Math.Clamp(size, 1, 65534) : DefaultBufferSize,
            AliveFlag = int.TryParse((string?)intern.Element("ALIVE")?.Attribute("Set_Flag"), CultureInfo.InvariantCulture, out int alive) ? alive : 0,
            Receive = [.. (root.Element("RECEIVE")?.Element("XML")?.Elements("ELEMENT") ?? []).Select(e => new EkiReceiveElement(
                (string?)e.Attribute("Tag") ?? throw new FormatException($"an ELEMENT of {name}.xml has no Tag"),
                ((string?)e.Attribute("Type"))?.ToUpperInvariant(),
                int.TryParse((string?)e.Attribute("Set_Flag"), CultureInfo.InvariantCulture, out int flag) ? flag : 0)),
                .. (rawReceive is null ? Array.Empty<EkiReceiveElement>() : new[] { new EkiReceiveElement(rawReceive.Tag, "STRING", rawReceive.SetFlag) })],
            Send = [.. (root.Element("SEND")?.Element("XML")?.Elements("ELEMENT") ?? []).Select(e => (string?)e.Attribute("Tag") ?? "")],
            RawReceive = rawReceive,
            RawSend = rawSend,
        };
    }

    /// <summary>The RAW element of a RECEIVE or SEND section (null when it has none); throws <see cref="FormatException"/> for one the package would refuse.</summary>
    private static EkiRawElement? Raw(string name, XElement? section)
    {
        XElement[] elements = [.. section?.Element("RAW")?.Elements("ELEMENT") ?? []];
        if (elements.Length == 0)
        {
            return null;
        }
        if (elements.Length > 1)
        {
            throw new FormatException($"the configuration {name}.xml has {elements.Length} RAW elements in <{section!.Name}>: binary data has one memory, so one element");
        }
        XElement e = elements[0];
        string tag = (string?)e.Attribute("Tag") ?? throw new FormatException($"the RAW ELEMENT of {name}.xml has no Tag");
        string type = ((string?)e.Attribute("Type") ?? "").Trim().ToUpperInvariant();
        if (type is not ("BYTE" or "STREAM"))
        {
            throw new FormatException($"the RAW ELEMENT {tag} of {name}.xml has Type \"{(string?)e.Attribute("Type")}\": BYTE (fixed length) or STREAM (with an end string)");
        }
        if (!int.TryParse((string?)e.Attribute("Size"), NumberStyles.None, CultureInfo.InvariantCulture, out int size) || size is < 1 or > 3600)
        {
            if (type == "BYTE" || e.Attribute("Size") is not null)
            {
                throw new FormatException($"the RAW ELEMENT {tag} of {name}.xml needs a Size of 1 to 3600 bytes");
            }
            size = 3600;
        }
        var ends = new List<byte[]>();
        if (type == "STREAM")
        {
            foreach (string alternative in ((string?)e.Attribute("EOS") ?? "").Split('|', StringSplitOptions.RemoveEmptyEntries | StringSplitOptions.TrimEntries))
            {
                byte[] end = [.. alternative.Split(',').Select(b => byte.TryParse(b.Trim(), NumberStyles.None, CultureInfo.InvariantCulture, out byte v)
                    ? v : throw new FormatException($"the EOS of RAW ELEMENT {tag} of {name}.xml is not a list of byte values (\"{alternative}\")"))];
                ends.Add(end.Length is >= 1 and <= 32 ? end : throw new FormatException($"an EOS of RAW ELEMENT {tag} of {name}.xml has {end.Length} bytes (1 to 32)"));
            }
            if (ends.Count == 0)
            {
                throw new FormatException($"the RAW ELEMENT {tag} of {name}.xml is a STREAM without an end string (EOS)");
            }
        }
        int setFlag = int.TryParse((string?)e.Attribute("Set_Flag"), CultureInfo.InvariantCulture, out int flag) ? flag : 0;
        return new EkiRawElement(tag, type == "STREAM", size, ends, setFlag);
    }
}
