using System.Text;

namespace Machina.Simulation.Krl;

/// <summary>
/// The XML document EKI_Send writes for an element of the SEND configuration: the element, its attributes whose values the
/// program set (in the configuration's order), and its configured child elements, nested as their tags say
/// (<c>RobotState/Pos/@A1</c> is attribute A1 of element Pos in RobotState). An element with a value set carries it as text.
/// </summary>
internal static class EkiSendDocument
{
    private sealed class Node(string name)
    {
        public string Name { get; } = name;

        public List<(string Name, string Value)> Attributes { get; } = [];

        public List<Node> Children { get; } = [];

        public string? Text { get; set; }

        public Node Child(string name)
        {
            Node? child = Children.Find(c => c.Name == name);
            if (child is null)
            {
                child = new Node(name);
                Children.Add(child);
            }
            return child;
        }
    }

    /// <summary>The document of element <paramref name="root"/> (a tag path) from the SEND <paramref name="tags"/> and the values set.</summary>
    public static string Write(string root, IReadOnlyList<string> tags, IReadOnlyDictionary<string, string> values)
    {
        if (FlatAttributes(root, tags) is { } attributes)
        {
            return WriteFlat(root, attributes, values);
        }
        var top = new Node(root[(root.LastIndexOf('/') + 1)..]);
        foreach (string tag in tags)
        {
            if (tag != root && !tag.StartsWith(root + "/", StringComparison.Ordinal))
            {
                continue;
            }
            Node node = top;
            string[] steps = tag.Length > root.Length ? tag[(root.Length + 1)..].Split('/') : [];
            bool set = values.TryGetValue(tag, out string? value);
            for (int i = 0; i < steps.Length; i++)
            {
                if (steps[i].StartsWith('@'))
                {
                    if (set)
                    {
                        node.Attributes.Add((steps[i][1..], value!));
                    }
                    node = null!;
                    break;
                }
                node = node.Child(steps[i]);
            }
            if (node is not null && set)
            {
                node.Text = value;
            }
            if (node is not null)
            {
                // A FRAME element's components (EKI_SetFrame) are its attributes.
                foreach (string component in EkiChannel.FrameComponents)
                {
                    if (values.TryGetValue(tag + "/@" + component, out string? part) && !tags.Contains(tag + "/@" + component))
                    {
                        node.Attributes.Add((component, part));
                    }
                }
            }
        }
        var xml = new StringBuilder();
        Append(xml, top);
        return xml.ToString();
    }

    /// <summary>
    /// The attribute tags of <paramref name="root"/> in the configuration's order when the element has only attributes (the Machina
    /// driver's acknowledgements), or null when it is written as a tree (a path, or elements below it). A channel keeps the answer
    /// per configured root: the configuration does not change.
    /// </summary>
    public static string[]? FlatAttributes(string root, IReadOnlyList<string> tags)
    {
        string prefix = root + "/@";
        if (root.Contains('/', StringComparison.Ordinal) || HasElementsBelow(root, tags, prefix))
        {
            return null;
        }
        var attributes = new List<string>();
        for (int i = 0; i < tags.Count; i++)
        {
            if (IsAttribute(tags[i], prefix))
            {
                attributes.Add(tags[i]);
            }
        }
        return [.. attributes];
    }

    /// <summary>The document of an element with only <paramref name="attributes"/> (see <see cref="FlatAttributes"/>), those set, in order.</summary>
    public static string WriteFlat(string root, string[] attributes, IReadOnlyDictionary<string, string> values)
    {
        char[] scratch = new char[64];
        return WriteFlat(root, attributes, values, ref scratch);
    }

    /// <summary>
    /// <see cref="WriteFlat(string, string[], IReadOnlyDictionary{string, string})"/> written in <paramref name="scratch"/> (grown
    /// when too small, kept by the caller between sends): one string a send, where a builder made the builder, its buffer and the
    /// string (the driver's acknowledgement, once an action).
    /// </summary>
    public static string WriteFlat(string root, string[] attributes, IReadOnlyDictionary<string, string> values, ref char[] scratch)
    {
        int length = WriteFlatChars(root, attributes, values, ref scratch); // first: it may give scratch a larger array
        return new string(scratch, 0, length);
    }

    /// <summary>
    /// The UTF-8 bytes of <see cref="WriteFlat(string, string[], IReadOnlyDictionary{string, string}, ref char[])"/>'s document,
    /// straight from <paramref name="scratch"/>: one array a send, where the text and then its bytes were two (EKI_Send hands the
    /// stack bytes; the driver's acknowledgement, once an action).
    /// </summary>
    public static byte[] WriteFlatBytes(string root, string[] attributes, IReadOnlyDictionary<string, string> values, ref char[] scratch)
    {
        int length = WriteFlatChars(root, attributes, values, ref scratch); // first: it may give scratch a larger array
        return Encoding.UTF8.GetBytes(scratch, 0, length);
    }

    /// <summary>Writes the flat document into <paramref name="scratch"/> (grown when too small); returns its length.</summary>
    private static int WriteFlatChars(string root, string[] attributes, IReadOnlyDictionary<string, string> values, ref char[] scratch)
    {
        int skip = root.Length + 2; // "root/@"
        int length = 0;
        Append(ref scratch, ref length, "<");
        Append(ref scratch, ref length, root);
        foreach (string tag in attributes)
        {
            if (values.TryGetValue(tag, out string? value))
            {
                Append(ref scratch, ref length, " ");
                Append(ref scratch, ref length, tag.AsSpan(skip));
                Append(ref scratch, ref length, "=\"");
                Append(ref scratch, ref length, EkiChannel.Escape(value));
                Append(ref scratch, ref length, "\"");
            }
        }
        Append(ref scratch, ref length, " />");
        return length;
    }

    private static void Append(ref char[] scratch, ref int length, ReadOnlySpan<char> text)
    {
        if (length + text.Length > scratch.Length)
        {
            Array.Resize(ref scratch, Math.Max(scratch.Length * 2, length + text.Length));
        }
        text.CopyTo(scratch.AsSpan(length));
        length += text.Length;
    }

    /// <summary>True when <paramref name="tags"/> name <paramref name="root"/> itself or an element below it (not only its attributes).</summary>
    private static bool HasElementsBelow(string root, IReadOnlyList<string> tags, string prefix)
    {
        for (int i = 0; i < tags.Count; i++)
        {
            string tag = tags[i];
            if (tag == root || (IsBelow(tag, root) && !IsAttribute(tag, prefix)))
            {
                return true;
            }
        }
        return false;
    }

    /// <summary>True when <paramref name="tag"/> is below <paramref name="root"/> (<c>root/…</c>).</summary>
    internal static bool IsBelow(string tag, string root) =>
        tag.Length > root.Length && tag[root.Length] == '/' && tag.StartsWith(root, StringComparison.Ordinal);

    private static bool IsAttribute(string tag, string prefix) => tag.StartsWith(prefix, StringComparison.Ordinal) && tag.IndexOf('/', prefix.Length) < 0;

    private static void Append(StringBuilder xml, Node node)
    {
        xml.Append('<').Append(node.Name);
        foreach ((string name, string value) in node.Attributes)
        {
            xml.Append(' ').Append(name).Append("=\"").Append(EkiChannel.Escape(value)).Append('"');
        }
        if (node.Children.Count == 0 && node.Text is null)
        {
            xml.Append(" />");
            return;
        }
        xml.Append('>');
        if (node.Text is not null)
        {
            xml.Append(EkiChannel.Escape(node.Text));
        }
        foreach (Node child in node.Children)
        {
            Append(xml, child);
        }
        xml.Append("</").Append(node.Name).Append('>');
    }
}
