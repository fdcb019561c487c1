using System.Globalization;

namespace Machina;

/// <summary>One XML element of the KUKA link: its name, attributes (in order), child elements and text, as received.</summary>
internal sealed class KukaElement
{
    /// <summary>Creates an element.</summary>
    public KukaElement(string name, IReadOnlyList<KeyValuePair<string, string>> attributes, IReadOnlyList<KukaElement> children, string text)
    {
        Name = name;
        Attributes = attributes;
        Children = children;
        Text = text;
    }

    /// <summary>The element's name (tag).</summary>
    public string Name { get; }

    /// <summary>The attributes with their decoded values, in the order received.</summary>
    public IReadOnlyList<KeyValuePair<string, string>> Attributes { get; }

    /// <summary>The child elements, in order.</summary>
    public IReadOnlyList<KukaElement> Children { get; }

    /// <summary>The decoded text directly inside the element (empty when none).</summary>
    public string Text { get; }

    /// <summary>The value of an attribute, or null when the element does not have it.</summary>
    public string? Attribute(string name)
    {
        IReadOnlyList<KeyValuePair<string, string>> attributes = Attributes;
        for (int i = 0; i < attributes.Count; i++) // by index: an enumerator through the interface is an object per look-up
        {
            if (attributes[i].Key == name)
            {
                return attributes[i].Value;
            }
        }
        return null;
    }

    /// <summary>A number attribute; a protocol error when it is missing or not a finite number.</summary>
    public double Number(string name)
    {
        string text = Attribute(name) ?? throw Missing(name);
        return double.TryParse(text, NumberStyles.Float, CultureInfo.InvariantCulture, out double value) && double.IsFinite(value)
            ? value
            : throw new KukaProtocolException($"The attribute {name}=\"{text}\" of <{Name}> is not a number.", ToString());
    }

    /// <summary>A whole-number attribute; a protocol error when it is missing or not an integer.</summary>
    public int Integer(string name)
    {
        string text = Attribute(name) ?? throw Missing(name);
        return int.TryParse(text, NumberStyles.AllowLeadingSign | NumberStyles.AllowLeadingWhite | NumberStyles.AllowTrailingWhite, CultureInfo.InvariantCulture, out int value)
            ? value
            : throw new KukaProtocolException($"The attribute {name}=\"{text}\" of <{Name}> is not a whole number.", ToString());
    }

    private KukaProtocolException Missing(string name) => new($"The element <{Name}> has no attribute {name}.", ToString());

    /// <summary>The element as XML text (for messages).</summary>
    public override string ToString()
    {
        var sb = new System.Text.StringBuilder();
        KukaXml.AppendStart(sb, Name);
        foreach (var pair in Attributes)
        {
            KukaXml.AppendAttribute(sb, pair.Key, pair.Value);
        }
        if (Children.Count == 0 && Text.Length == 0)
        {
            return sb.Append("/>").ToString();
        }
        sb.Append('>');
        KukaXml.AppendText(sb, Text);
        foreach (KukaElement child in Children)
        {
            sb.Append(child);
        }
        return sb.Append("</").Append(Name).Append('>').ToString();
    }
}
