using System.Text;
using System.Xml.Linq;

namespace Machina.Simulation.Rws;

/// <summary>Writes the XHTML answers of RWS 1.0: a <c>div class="state"</c> of <c>li</c> items with <c>span</c> values, or a <c>div class="status"</c> error.</summary>
internal static class RwsXhtmlWriter
{
    private static readonly XNamespace Xhtml = "http://www.w3.org/1999/xhtml";

    /// <summary>One item: its class, title and values (class, text).</summary>
    public static XElement Item(string cls, string title, params (string Class, string Value)[] spans) =>
        new(Xhtml + "li", new XAttribute("class", cls), new XAttribute("title", title),
            spans.Select(s => new XElement(Xhtml + "span", new XAttribute("class", s.Class), s.Value)));

    /// <summary>A link (<c>a href rel</c>), as events name their resource with <c>rel="self"</c>.</summary>
    public static XElement Link(string href, string rel) => new(Xhtml + "a", new XAttribute("href", href), new XAttribute("rel", rel));

    /// <summary>The XHTML of a subscription's event: the items of the resources that changed, in the group of subscription <paramref name="group"/>.</summary>
    public static byte[] EventDocument(int group, IEnumerable<XElement> items) =>
        Document("event", new XElement(Xhtml + "div", new XAttribute("class", "state"), Link($"subscription/{group}", "group"), new XElement(Xhtml + "ul", items)));

    /// <summary>A 200 answer titled <paramref name="title"/> with <paramref name="items"/>.</summary>
    public static RwsResponse State(string title, IEnumerable<XElement> items) =>
        new(200, "OK", Document(title, new XElement(Xhtml + "div", new XAttribute("class", "state"), new XElement(Xhtml + "ul", items))));

    /// <summary>A 200 answer with one item.</summary>
    public static RwsResponse State(string title, XElement item) => State(title, [item]);

    /// <summary>An error answer: HTTP <paramref name="status"/>, the controller's <paramref name="code"/> (when known) and <paramref name="message"/>.</summary>
    public static RwsResponse Error(int status, string reason, long? code, string message)
    {
        var div = new XElement(Xhtml + "div", new XAttribute("class", "status"));
        if (code is { } c)
        {
            div.Add(new XElement(Xhtml + "span", new XAttribute("class", "code"), c));
        }
        div.Add(new XElement(Xhtml + "span", new XAttribute("class", "msg"), message));
        return new RwsResponse(status, reason, Document("rw", div));
    }

    private static byte[] Document(string title, XElement content)
    {
        var html = new XElement(Xhtml + "html",
            new XElement(Xhtml + "head", new XElement(Xhtml + "title", title)),
            new XElement(Xhtml + "body", content));
        return Encoding.UTF8.GetBytes("<?xml version=\"1.0\" encoding=\"UTF-8\"?>" + html.ToString(SaveOptions.DisableFormatting));
    }
}
