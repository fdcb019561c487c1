using System.Globalization;
using System.Xml;
using System.Xml.Linq;

namespace Machina;

/// <summary>
/// Reads the XHTML answers of Robot Web Services: each value is a <c>&lt;span class="name"&gt;value&lt;/span&gt;</c> inside a
/// <c>&lt;li class="resource"&gt;</c>; an error is a <c>&lt;div class="status"&gt;</c> with a <c>code</c> and a <c>msg</c>.
/// </summary>
internal static class RwsXhtml
{
    /// <summary>
    /// The deepest nesting of elements read (an answer is html/body/div/ul/li/span, under ten deep): deeper answers are refused
    /// before they are walked, which keeps reading them linear in their size.
    /// </summary>
    public const int MaxDepth = 32;

    /// <summary>The items (<c>li</c>) of an answer, each as its class, title and spans by class.</summary>
    public static IReadOnlyList<RwsItem> Items(string text)
    {
        XDocument doc = Parse(text);
        return [.. doc.Descendants().Where(e => e.Name.LocalName == "li").Select(li => new RwsItem(
            (string?)li.Attribute("class") ?? "",
            (string?)li.Attribute("title") ?? "",
            Spans(li)))];
    }

    /// <summary>The text of the first span of class <paramref name="name"/>; throws when the answer has none.</summary>
    public static string Value(string text, string name) =>
        Spans(Parse(text).Root!).GetValueOrDefault(name)
        ?? throw new RobotWebServicesException($"The controller's answer has no \"{name}\" value: {Shorten(text)}", 200, null);

    /// <summary>The code and message of an error answer (both null when the answer has no status).</summary>
    public static (long? Code, string? Message) Status(string text)
    {
        try
        {
            Dictionary<string, string> spans = Spans(Parse(text).Root!);
            long? code = spans.TryGetValue("code", out string? c) && long.TryParse(c, NumberStyles.Integer, CultureInfo.InvariantCulture, out long n) ? n : null;
            return (code, spans.GetValueOrDefault("msg"));
        }
        catch (RobotWebServicesException)
        {
            return (null, null);
        }
    }

    /// <summary>A number from an answer, read the invariant way.</summary>
    public static double Number(string value, string what) =>
        double.TryParse(value, NumberStyles.Float, CultureInfo.InvariantCulture, out double d)
            ? d
            : throw new RobotWebServicesException($"The controller's {what} \"{value}\" is not a number.", 200, null);

    /// <summary>At most 200 characters of an answer, for a message, made printable (escape codes written as <c>\x1b</c>).</summary>
    public static string Shorten(string text) => PrintableText.Of(text.Length <= 200 ? text : text[..200] + "…");

    private static Dictionary<string, string> Spans(XElement root)
    {
        var spans = new Dictionary<string, string>(StringComparer.Ordinal);
        foreach (XElement span in root.DescendantsAndSelf().Where(e => e.Name.LocalName == "span"))
        {
            string? name = ((string?)span.Attribute("class"))?.Trim();
            if (name is not null && !spans.ContainsKey(name))
            {
                spans[name] = span.Value;
            }
        }
        return spans;
    }

    private static XDocument Parse(string text)
    {
        try
        {
            var settings = new XmlReaderSettings { DtdProcessing = DtdProcessing.Prohibit, XmlResolver = null };
            using (var reader = XmlReader.Create(new StringReader(text), settings))
            {
                while (reader.Read())
                {
                    if (reader.Depth > MaxDepth)
                    {
                        throw new RobotWebServicesException(
                            $"The controller's answer nests elements more than {MaxDepth} deep; it is not the XHTML of Robot Web Services: {Shorten(text)}", 200, null);
                    }
                }
            }
            return XDocument.Parse(text);
        }
        catch (XmlException ex)
        {
            throw new RobotWebServicesException($"The controller's answer is not the XHTML of Robot Web Services: {Shorten(text)}", 200, null, ex);
        }
    }
}

/// <summary>One item of a Robot Web Services answer: its class, its title and its values by class.</summary>
internal sealed record RwsItem(string Class, string Title, IReadOnlyDictionary<string, string> Values);
