using System.Globalization;
using System.Xml.Linq;

namespace Machina.Simulation.Krl;

/// <summary>One ELEMENT of an RSI Ethernet configuration: its TAG, TYPE, INDX (null for INTERNAL, the DEF_ values) and HOLDON.</summary>
internal sealed record RsiElement(string Tag, string Type, int? Index, bool HoldOn);

/// <summary>
/// The configuration file of an RSI ETHERNET object (C:\KRC\ROBOTER\Config\User\Common\SensorInterface\*.xml): the sensor's
/// IP_NUMBER and PORT, the SENTYPE the robot names itself with, ONLYSEND, and the SEND and RECEIVE elements.
/// </summary>
internal sealed class RsiEthernetConfiguration
{
    /// <summary>The DEF_ elements (INDX="INTERNAL") the twin sends, as the robot's own values.</summary>
    public static readonly string[] Internal = ["DEF_RIst", "DEF_RSol", "DEF_AIPos", "DEF_ASPos", "DEF_EIPos", "DEF_ESPos", "DEF_Delay"];

    /// <summary>The sensor's address (IP_NUMBER).</summary>
    public string Address { get; private init; } = "";

    /// <summary>The sensor's port (PORT).</summary>
    public int Port { get; private init; }

    /// <summary>SENTYPE: the Type attribute of the robot's &lt;Rob&gt; document.</summary>
    public string SenType { get; private init; } = "";

    /// <summary>ONLYSEND TRUE: the sensor sends nothing back, the robot only sends.</summary>
    public bool OnlySend { get; private init; }

    /// <summary>The elements the robot sends each cycle, in order.</summary>
    public IReadOnlyList<RsiElement> Send { get; private init; } = [];

    /// <summary>The elements the robot reads from the sensor's answer; INDX is the ETHERNET object's output.</summary>
    public IReadOnlyList<RsiElement> Receive { get; private init; } = [];

    /// <summary>Reads configuration <paramref name="file"/>; a mistake is a <see cref="FormatException"/> naming it.</summary>
    public static RsiEthernetConfiguration Parse(string file, string xml)
    {
        XElement root = RsiContext.RootOf($"the Ethernet configuration {file}", xml);
        XElement config = root.Element("CONFIG") ?? throw new FormatException($"RSI: the Ethernet configuration {file} has no CONFIG");
        string Value(string name) => ((string?)config.Element(name) ?? "").Trim();
        if (Value("PROTOCOL") is { Length: > 0 } protocol && !protocol.Equals("UDP", StringComparison.OrdinalIgnoreCase))
        {
            throw new FormatException($"RSI: the Ethernet configuration {file} asks for PROTOCOL {protocol}: the twin's RSI exchanges UDP datagrams");
        }
        if (!int.TryParse(Value("PORT"), NumberStyles.None, CultureInfo.InvariantCulture, out int port) || port is < 1 or > 65535)
        {
            throw new FormatException($"RSI: the Ethernet configuration {file} has no valid PORT (\"{Value("PORT")}\")");
        }
        return new RsiEthernetConfiguration
        {
            Address = Value("IP_NUMBER"),
            Port = port,
            SenType = Value("SENTYPE"),
            OnlySend = Value("ONLYSEND").Equals("TRUE", StringComparison.OrdinalIgnoreCase),
            Send = Elements(file, root.Element("SEND"), send: true),
            Receive = Elements(file, root.Element("RECEIVE"), send: false),
        };
    }

    private static List<RsiElement> Elements(string file, XElement? section, bool send)
    {
        List<RsiElement> elements = [];
        foreach (XElement element in section?.Element("ELEMENTS")?.Elements("ELEMENT") ?? [])
        {
            string tag = (string?)element.Attribute("TAG") ?? throw new FormatException($"RSI: an ELEMENT of {file} has no TAG");
            string index = ((string?)element.Attribute("INDX") ?? "").Trim();
            int? number = null;
            if (index.Equals("INTERNAL", StringComparison.OrdinalIgnoreCase))
            {
                if (!send || !Internal.Contains(tag, StringComparer.OrdinalIgnoreCase))
                {
                    throw new FormatException($"RSI: {file}: the internal element {tag} is not supported by the twin (it sends {string.Join(", ", Internal)})");
                }
            }
            else if (int.TryParse(index, NumberStyles.None, CultureInfo.InvariantCulture, out int n) && n is >= 1 and <= 64)
            {
                number = n;
            }
            else
            {
                throw new FormatException($"RSI: {file}: the element {tag} has INDX \"{index}\" (1 to 64, or INTERNAL)");
            }
            elements.Add(new RsiElement(tag, ((string?)element.Attribute("TYPE") ?? "DOUBLE").ToUpperInvariant(), number, (string?)element.Attribute("HOLDON") == "1"));
        }
        return elements;
    }
}
