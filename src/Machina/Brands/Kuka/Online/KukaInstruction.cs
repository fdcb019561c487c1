using System.Runtime.CompilerServices;
using System.Text;

namespace Machina;

/// <summary>The parameters of a KUKA action (<c>V1</c>…<c>V7</c>, and a CIRC's auxiliary point in <c>V8</c>…<c>V13</c>), in KRL units.</summary>
[InlineArray(KukaProtocol.CircularValueCount)]
internal struct KukaValues
{
    private double _first;
}

/// <summary>One action as the KRL driver reads it: <c>&lt;A ID="…" T="…" V1="…" … V7="…" M="…"/&gt;</c> (a CIRC: V1 … V13).</summary>
/// <param name="Id">The action's id (acknowledged by the driver).</param>
/// <param name="Code">What the driver does.</param>
/// <param name="Values">Parameters in KRL units (mm, degrees, m/s, seconds), unused ones 0.</param>
/// <param name="Text">The message text (empty for every other action).</param>
internal readonly record struct KukaInstruction(int Id, KukaActionCode Code, KukaValues Values, string Text)
{
    /// <summary>
    /// Appends the action's element. Every action carries every attribute up to V7 (the driver reads each attribute from its own
    /// queue); a CIRC also carries V8…V13, which the driver reads only for a CIRC.
    /// </summary>
    public void AppendTo(StringBuilder sb)
    {
        KukaXml.AppendStart(sb, KukaProtocol.Action);
        sb.Append(" ID=\"").Append(Id).Append("\" T=\"").Append((int)Code).Append('"');
        KukaValues values = Values;
        for (int i = 0; i < KukaProtocol.ValueCountOf(Code); i++)
        {
            KukaXml.AppendAttribute(sb, KukaProtocol.ValueNames[i], values[i]);
        }
        KukaXml.AppendAttribute(sb, "M", Text).Append("/>");
    }

    /// <summary>Appends one batch: <c>&lt;DT&gt;&lt;DR&gt;</c>, the actions, <c>&lt;/DR&gt;&lt;/DT&gt;</c>.</summary>
    public static void AppendBatch(StringBuilder sb, IEnumerable<KukaInstruction> actions)
    {
        sb.Append("<DT><DR>");
        foreach (KukaInstruction action in actions)
        {
            action.AppendTo(sb);
        }
        sb.Append("</DR></DT>");
    }

    /// <summary>Appends a batch of one action (what the host streams: no list, no enumerator).</summary>
    public static void AppendBatch(StringBuilder sb, in KukaInstruction action)
    {
        sb.Append("<DT><DR>");
        action.AppendTo(sb);
        sb.Append("</DR></DT>");
    }

    /// <summary>Characters enough for a batch of one action without text (<see cref="TryWriteBatch"/>): 13 values of at most 32 characters and the markup.</summary>
    public const int MaxPlainBatchChars = 640;

    /// <summary>
    /// Writes the batch of this one action, the same characters as <see cref="AppendBatch(StringBuilder, in KukaInstruction)"/>,
    /// into <paramref name="destination"/> (at least <see cref="MaxPlainBatchChars"/> long) and returns their count; −1 when the
    /// action has a text or a value the fixed-point writer does not take (the caller appends it to a builder). What the host
    /// streams: a move's batch without a builder per action.
    /// </summary>
    public int TryWriteBatch(Span<char> destination)
    {
        if (Text.Length != 0)
        {
            return -1;
        }
        int at = Put(destination, 0, "<DT><DR><A ID=\"");
        Id.TryFormat(destination[at..], out int written, default, System.Globalization.CultureInfo.InvariantCulture);
        at = Put(destination, at + written, "\" T=\"");
        ((int)Code).TryFormat(destination[at..], out written, default, System.Globalization.CultureInfo.InvariantCulture);
        at = Put(destination, at + written, "\"");
        KukaValues values = Values;
        for (int i = 0; i < KukaProtocol.ValueCountOf(Code); i++)
        {
            at = Put(destination, Put(destination, at, " "), KukaProtocol.ValueNames[i]);
            at = Put(destination, at, "=\"");
            written = NumAppend.TryWriteScaled(destination[at..], values[i], 6);
            if (written < 0)
            {
                return -1;
            }
            at = Put(destination, at + written, "\"");
        }
        return Put(destination, at, " M=\"\"/></DR></DT>");
    }

    private static int Put(Span<char> destination, int at, ReadOnlySpan<char> text)
    {
        text.CopyTo(destination[at..]);
        return at + text.Length;
    }

    /// <summary>Reads an action element back (the virtual controller's side); a protocol error when an attribute is missing or malformed.</summary>
    public static KukaInstruction Parse(KukaElement element)
    {
        int code = element.Integer("T");
        if (!Enum.IsDefined((KukaActionCode)code))
        {
            throw new KukaProtocolException($"The action type T=\"{code}\" is not one the driver knows.", element.ToString());
        }
        var values = new KukaValues();
        for (int i = 0; i < KukaProtocol.ValueCountOf((KukaActionCode)code); i++)
        {
            values[i] = element.Number(KukaProtocol.ValueNames[i]);
        }
        return new KukaInstruction(element.Integer("ID"), (KukaActionCode)code, values,
            element.Attribute("M") ?? throw new KukaProtocolException("The action has no message attribute M.", element.ToString()));
    }
}
