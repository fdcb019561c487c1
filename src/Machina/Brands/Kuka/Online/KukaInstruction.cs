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
        var text = new KukaText(sb);
        WriteTo(ref text);
    }

    /// <summary>Writes the action's element (<see cref="AppendTo"/>): the one writer of the format, into a span or a builder.</summary>
    private void WriteTo(ref KukaText text)
    {
        text.Append("<A ID=\"");
        text.Append(Id);
        text.Append("\" T=\"");
        text.Append((int)Code);
        text.Append("\"");
        KukaValues values = Values;
        for (int i = 0; i < KukaProtocol.ValueCountOf(Code); i++)
        {
            text.Append(" ");
            text.Append(KukaProtocol.ValueNames[i]);
            text.Append("=\"");
            text.AppendFixed(values[i], 6);
            text.Append("\"");
        }
        text.Append(" M=\"");
        text.AppendEscaped(Text);
        text.Append("\"/>");
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
        var text = new KukaText(sb);
        action.WriteBatch(ref text);
    }

    /// <summary>Characters a batch of one action takes on the stack (<see cref="WriteBatch(Span{char})"/>): 13 values of at most 32 characters, the markup and a short message.</summary>
    public const int StackBatchChars = 1024;

    /// <summary>
    /// Writes the batch of this one action (the characters of <see cref="AppendBatch(StringBuilder, in KukaInstruction)"/>) into
    /// <paramref name="destination"/> while it fits and every value takes the fixed-point writer (below 10^9), else on into a
    /// builder: the returned text's <see cref="KukaText.Builder"/> is null when all of it is in the span. What the host streams.
    /// </summary>
    public KukaText WriteBatch(Span<char> destination)
    {
        var text = new KukaText(destination);
        WriteBatch(ref text);
        return text;
    }

    private void WriteBatch(ref KukaText text)
    {
        text.Append("<DT><DR>");
        WriteTo(ref text);
        text.Append("</DR></DT>");
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
