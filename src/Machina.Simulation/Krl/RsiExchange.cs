using System.Globalization;
using System.Net;
using System.Net.Sockets;
using System.Text;
using System.Xml.Linq;

namespace Machina.Simulation.Krl;

/// <summary>What the robot reports of itself in an RSI cycle: actual and commanded Cartesian pose (X…C) and axes (A1…A6).</summary>
internal sealed record RsiRobotValues(double[] Actual, double[] Commanded, double[] ActualAxes, double[] CommandedAxes);

/// <summary>
/// The UDP exchange of an RSI ETHERNET object: each cycle the robot sends one XML document, &lt;Rob Type="SENTYPE"&gt; with the
/// SEND elements and &lt;IPOC&gt;, to the sensor at IP_NUMBER:PORT from a port of its own, and reads the sensor's &lt;Sen&gt;
/// answer carrying the same IPOC; an answer with another IPOC is a late one and is dropped.
/// </summary>
internal sealed class RsiExchange : IDisposable
{
    private static readonly string[] Cartesian = ["X", "Y", "Z", "A", "B", "C"];
    private static readonly string[] AxisNames = ["A1", "A2", "A3", "A4", "A5", "A6"];
    private static readonly string[] ExternalNames = ["E1", "E2", "E3", "E4", "E5", "E6"];
    private readonly Socket _socket;
    private readonly EndPoint _sensor;
    private readonly byte[] _buffer = new byte[65536];
    private readonly string _format;

    /// <summary>An exchange with the sensor <paramref name="configuration"/> names, numbers written with <paramref name="precision"/> decimals.</summary>
    public RsiExchange(RsiEthernetConfiguration configuration, int precision)
    {
        Configuration = configuration;
        if (!IPAddress.TryParse(configuration.Address, out IPAddress? address))
        {
            throw new KrlRuntimeException($"RSI: the sensor's IP_NUMBER \"{configuration.Address}\" is not an IP address");
        }
        _sensor = new IPEndPoint(address, configuration.Port);
        _socket = new Socket(address.AddressFamily, SocketType.Dgram, ProtocolType.Udp);
        _socket.Bind(new IPEndPoint(address.AddressFamily == AddressFamily.InterNetworkV6 ? IPAddress.IPv6Any : IPAddress.Any, 0));
        _format = "0." + new string('#', Math.Clamp(precision, 1, 32));
    }

    /// <summary>The ETHERNET object's configuration.</summary>
    public RsiEthernetConfiguration Configuration { get; }

    /// <summary>The robot's document of one cycle: the SEND elements (the DEF_ ones from <paramref name="robot"/>, the others from <paramref name="inputs"/> by INDX).</summary>
    public string Document(RsiRobotValues robot, double[] inputs, int delay, long ipoc)
    {
        var text = new StringBuilder(512);
        text.Append("<Rob Type=\"").Append(Configuration.SenType).Append("\">");
        var grouped = new List<(string Element, List<(string Attribute, string Value)> Attributes, string? Text)>();
        foreach (RsiElement element in Configuration.Send)
        {
            switch (element.Index is null ? element.Tag.ToUpperInvariant() : "")
            {
                case "DEF_RIST": Values(text, "RIst", Cartesian, robot.Actual); continue;
                case "DEF_RSOL": Values(text, "RSol", Cartesian, robot.Commanded); continue;
                case "DEF_AIPOS": Values(text, "AIPos", AxisNames, robot.ActualAxes); continue;
                case "DEF_ASPOS": Values(text, "ASPos", AxisNames, robot.CommandedAxes); continue;
                case "DEF_EIPOS": Values(text, "EIPos", ExternalNames, new double[6]); continue;
                case "DEF_ESPOS": Values(text, "ESPos", ExternalNames, new double[6]); continue;
                case "DEF_DELAY": text.Append(CultureInfo.InvariantCulture, $"<Delay D=\"{delay}\" />"); continue;
            }
            string value = Format(element.Type, inputs[element.Index!.Value]);
            int dot = element.Tag.IndexOf('.', StringComparison.Ordinal);
            string name = dot < 0 ? element.Tag : element.Tag[..dot];
            int at = grouped.FindIndex(g => g.Element == name && dot >= 0 && g.Text is null);
            if (at < 0)
            {
                grouped.Add((name, [], dot < 0 ? value : null));
                at = grouped.Count - 1;
            }
            if (dot >= 0)
            {
                grouped[at].Attributes.Add((element.Tag[(dot + 1)..], value));
            }
        }
        foreach ((string element, List<(string Attribute, string Value)> attributes, string? inner) in grouped)
        {
            text.Append('<').Append(element);
            foreach ((string attribute, string value) in attributes)
            {
                text.Append(' ').Append(attribute).Append("=\"").Append(value).Append('"');
            }
            text.Append(inner is null ? " />" : $">{inner}</{element}>");
        }
        text.Append(CultureInfo.InvariantCulture, $"<IPOC>{ipoc}</IPOC></Rob>");
        return text.ToString();
    }

    private void Values(StringBuilder text, string element, string[] names, double[] values)
    {
        text.Append('<').Append(element);
        for (int i = 0; i < names.Length; i++)
        {
            text.Append(' ').Append(names[i]).Append("=\"").Append(values[i].ToString(_format, CultureInfo.InvariantCulture)).Append('"');
        }
        text.Append(" />");
    }

    private string Format(string type, double value) => type switch
    {
        "BOOL" => value != 0 ? "1" : "0",
        "LONG" => Math.Round(value).ToString(CultureInfo.InvariantCulture),
        _ => value.ToString(_format, CultureInfo.InvariantCulture),
    };

    /// <summary>Sends the robot's document to the sensor.</summary>
    public void Send(string document) => _socket.SendTo(Encoding.UTF8.GetBytes(document), _sensor);

    /// <summary>
    /// Waits until <paramref name="deadline"/> (a <see cref="TimeProvider"/> timestamp of <paramref name="time"/>) for the sensor's
    /// answer to <paramref name="ipoc"/>; answers to earlier cycles are dropped. The answer's document, or null when none came in time.
    /// </summary>
    public XElement? Answer(long ipoc, TimeProvider time, long deadline, CancellationToken cancellation)
    {
        while (true)
        {
            cancellation.ThrowIfCancellationRequested();
            TimeSpan left = time.GetElapsedTime(time.GetTimestamp(), deadline);
            int micros = (int)Math.Clamp(left.TotalMicroseconds, 0, 20_000);
            if (!_socket.Poll(micros, SelectMode.SelectRead))
            {
                if (left <= TimeSpan.Zero)
                {
                    return null;
                }
                continue;
            }
            EndPoint from = new IPEndPoint(IPAddress.Any, 0);
            int length;
            try
            {
                length = _socket.ReceiveFrom(_buffer, ref from);
            }
            catch (SocketException)
            {
                continue; // an ICMP "port unreachable" of an earlier datagram: nobody listened then
            }
            XElement? answer;
            try
            {
                answer = XDocument.Parse(Encoding.UTF8.GetString(_buffer, 0, length)).Root;
            }
            catch (System.Xml.XmlException)
            {
                continue; // not a document: dropped, as the cycle's answer is still missing
            }
            if (answer?.Element("IPOC") is { } stamp && long.TryParse(stamp.Value.Trim(), NumberStyles.Integer, CultureInfo.InvariantCulture, out long echoed) && echoed == ipoc)
            {
                return answer;
            }
        }
    }

    /// <summary>
    /// Puts the RECEIVE elements of <paramref name="answer"/> (null: none arrived) into <paramref name="outputs"/> by INDX: a tag
    /// "AK.A1" is attribute A1 of element AK, a tag without a dot an element's text. A value missing keeps its last one with
    /// HOLDON="1", else it is 0.
    /// </summary>
    public void Read(XElement? answer, double[] outputs)
    {
        foreach (RsiElement element in Configuration.Receive)
        {
            int dot = element.Tag.IndexOf('.', StringComparison.Ordinal);
            XElement? holder = answer?.Element(dot < 0 ? element.Tag : element.Tag[..dot]);
            string? text = dot < 0 ? holder?.Value : (string?)holder?.Attribute(element.Tag[(dot + 1)..]);
            if (text is not null && (text.Trim() is "TRUE" or "true" ? 1 : double.TryParse(text, NumberStyles.Float, CultureInfo.InvariantCulture, out double v) ? v : double.NaN) is var value && !double.IsNaN(value))
            {
                outputs[element.Index!.Value] = value;
            }
            else if (!element.HoldOn)
            {
                outputs[element.Index!.Value] = 0;
            }
        }
    }

    /// <inheritdoc/>
    public void Dispose() => _socket.Dispose();
}
