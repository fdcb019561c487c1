using System.Globalization;
using System.Xml.Linq;

namespace Machina.Simulation.Krl;

/// <summary>An input of an RSI object: which object's output (1-based) feeds it.</summary>
internal sealed record RsiLink(string Source, int Output);

/// <summary>
/// An RSI object of a context: its type (ETHERNET, AXISCORR, …, upper case), its name, its parameters by name (the twin reads
/// them as numbers, ConfigFile as text) and its inputs by index (1-based).
/// </summary>
internal sealed class RsiObject(string type, string id)
{
    /// <summary>The object type, upper case (ETHERNET, AXISCORR, AXISCORRMON, STOP, MONITOR, DIGIN, DIGOUT, MAP2DIGOUT).</summary>
    public string Type { get; } = type.ToUpperInvariant();

    /// <summary>The object's name in its context (ObjId).</summary>
    public string Id { get; } = id;

    /// <summary>The parameters, by name.</summary>
    public Dictionary<string, string> Parameters { get; } = new(StringComparer.OrdinalIgnoreCase);

    /// <summary>The inputs, by 1-based index.</summary>
    public Dictionary<int, RsiLink> Inputs { get; } = [];

    /// <summary>Parameter <paramref name="name"/> as a number, or <paramref name="otherwise"/> when it is not set.</summary>
    public double Number(string name, double otherwise) =>
        Parameters.TryGetValue(name, out string? text) && double.TryParse(text, NumberStyles.Float, CultureInfo.InvariantCulture, out double value) ? value : otherwise;
}

/// <summary>
/// An RSI context, the signal flow RSI_CREATE loads: from a <c>.rsix</c> file (RSI 4, made by RSIVisual in WorkVisual; its
/// RsiObjects list, indices from 0) or a <c>.rsi.xml</c> file (RSI 3; its RSIObjects list, indices from 1). The twin runs the
/// objects the published RSI clients use; any other object type refuses the context with its name (docs/simulation.md).
/// </summary>
internal sealed class RsiContext
{
    /// <summary>The object types the twin runs.</summary>
    public static readonly string[] Supported = ["ETHERNET", "AXISCORR", "AXISCORRMON", "STOP", "MONITOR", "DIGIN", "DIGOUT", "MAP2DIGOUT"];

    /// <summary>The context's name (its file name).</summary>
    public string Name { get; private init; } = "";

    /// <summary>The objects, in the file's order.</summary>
    public List<RsiObject> Objects { get; } = [];

    /// <summary>The object called <paramref name="id"/>, or null.</summary>
    public RsiObject? Find(string id) => Objects.Find(o => string.Equals(o.Id, id, StringComparison.OrdinalIgnoreCase));

    /// <summary>The root element of an RSI file's <paramref name="xml"/>; text that is not XML is a <see cref="FormatException"/> naming <paramref name="what"/>.</summary>
    internal static XElement RootOf(string what, string xml)
    {
        try
        {
            return XDocument.Parse(xml).Root!;
        }
        catch (System.Xml.XmlException ex)
        {
            throw new FormatException($"RSI: {what} is not XML: {ex.Message}");
        }
    }

    /// <summary>An empty context (RSI 2's ST_ routines build theirs object by object).</summary>
    public static RsiContext Empty(string name) => new() { Name = name };

    /// <summary>Reads context file <paramref name="file"/> (.rsix or .rsi.xml); a mistake or an object the twin lacks is a <see cref="FormatException"/>.</summary>
    public static RsiContext Parse(string file, string xml)
    {
        XElement root = RootOf($"the context {file}", xml);
        int first = file.EndsWith(".rsix", StringComparison.OrdinalIgnoreCase) ? 0 : 1;
        var context = new RsiContext { Name = file };
        string? Attribute(XElement e, string name) =>
            e.Attributes().FirstOrDefault(a => a.Name.LocalName.Equals(name, StringComparison.OrdinalIgnoreCase))?.Value;
        XElement objects = root.DescendantsAndSelf().FirstOrDefault(e => e.Name.LocalName.Equals("RsiObjects", StringComparison.OrdinalIgnoreCase))
            ?? throw new FormatException($"RSI: the context {file} has no RsiObjects list");
        foreach (XElement element in objects.Elements().Where(e => e.Name.LocalName.Equals("RsiObject", StringComparison.OrdinalIgnoreCase)))
        {
            var rsiObject = new RsiObject(Attribute(element, "ObjType") ?? "", Attribute(element, "ObjId") ?? "");
            if (!Supported.Contains(rsiObject.Type))
            {
                throw new FormatException($"RSI: the context {file} has the object {rsiObject.Id} of type {rsiObject.Type}, which the twin does not run (it runs {string.Join(", ", Supported)})");
            }
            foreach (XElement input in element.Descendants().Where(e => e.Name.LocalName == "Input"))
            {
                int index = int.Parse(Attribute(input, "InIdx") ?? "0", CultureInfo.InvariantCulture) - first + 1;
                int output = int.Parse(Attribute(input, "OutIdx") ?? "0", CultureInfo.InvariantCulture) - first + 1;
                rsiObject.Inputs[index] = new RsiLink(Attribute(input, "OutObjId") ?? "", output);
            }
            foreach (XElement parameter in element.Descendants().Where(e => e.Name.LocalName == "Parameter"))
            {
                rsiObject.Parameters[Attribute(parameter, "Name") ?? ""] = Attribute(parameter, "ParamValue") ?? "";
            }
            context.Objects.Add(rsiObject);
        }
        foreach (RsiObject o in context.Objects)
        {
            foreach (RsiLink link in o.Inputs.Values.Where(l => context.Find(l.Source) is null))
            {
                throw new FormatException($"RSI: the context {file}: the object {o.Id} is linked to {link.Source}, which it does not have");
            }
        }
        return context;
    }
}
