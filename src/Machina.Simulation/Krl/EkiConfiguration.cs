using System.Globalization;
using System.Xml.Linq;

namespace Machina.Simulation.Krl;

/// <summary>A value memory of an EthernetKRL channel: the tag of an element or attribute received, its type and the flag it sets.</summary>
/// <param name="Tag">The XML path, e.g. <c>DT/DR/A/@ID</c> (an attribute) or <c>DT</c> (an element).</param>
/// <param name="Type">INT, REAL, BOOL or STRING (null for an element that only sets a flag).</param>
/// <param name="SetFlag">The $FLAG set when the element has been received (0: none).</param>
internal sealed record EkiReceiveElement(string Tag, string? Type, int SetFlag);

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
                int.TryParse((string?)e.Attribute("Set_Flag"), CultureInfo.InvariantCulture, out int flag) ? flag : 0))],
            Send = [.. (root.Element("SEND")?.Element("XML")?.Elements("ELEMENT") ?? []).Select(e => (string?)e.Attribute("Tag") ?? "")],
        };
    }
}
