using System.Runtime.CompilerServices;
using System.Text;

namespace Machina;

/// <summary>Builds instruction texts (<c>Name(arg,arg);</c>) with lossless invariant numbers and escaped strings.</summary>
internal static class InstructionText
{
    /// <summary>A string argument in double quotes, with <c>\</c>, <c>"</c>, control characters and lone surrogates escaped.</summary>
    internal static string Quote(string value)
    {
        var sb = new StringBuilder(value.Length + 2);
        sb.Append('"');
        for (int i = 0; i < value.Length; i++)
        {
            char c = value[i];
            switch (c)
            {
                case '"': sb.Append("\\\""); break;
                case '\\': sb.Append("\\\\"); break;
                case '\n': sb.Append("\\n"); break;
                case '\r': sb.Append("\\r"); break;
                case '\t': sb.Append("\\t"); break;
                default:
                    // Control characters, Unicode line and paragraph separators (which editors show as line breaks) and lone
                    // surrogate halves (which no file encoding can hold) are written as \uXXXX.
                    if (char.IsControl(c) || c is '\u2028' or '\u2029' || (char.IsSurrogate(c) && !char.IsSurrogatePair(value, i) && !(i > 0 && char.IsSurrogatePair(value, i - 1))))
                    {
                        sb.Append("\\u").Append(((int)c).ToString("x4", Num.Inv));
                    }
                    else
                    {
                        sb.Append(c);
                    }
                    break;
            }
        }
        sb.Append('"');
        return sb.ToString();
    }

    /// <summary>Boolean argument as the original wrote it: <c>True</c> or <c>False</c>.</summary>
    internal static string Bool(bool value) => value ? "True" : "False";

    /// <summary><c>Name(n1,n2,…);</c> with lossless numbers.</summary>
    internal static string Call(string name, params ReadOnlySpan<double> values) => Call(name, null, values, null);

    /// <summary>
    /// <c>Name(first,n1,n2,…,last);</c>: lossless numbers between optional already-formatted arguments
    /// (a quoted name before them, a flag or target after them).
    /// </summary>
    /// <remarks>Formats into a stack buffer so that only the final string is allocated (compiling a million moves calls this a million times).</remarks>
    internal static string Call(string name, string? first, ReadOnlySpan<double> values, string? last)
    {
        var text = new DefaultInterpolatedStringHandler(0, 0, Num.Inv, stackalloc char[256]);
        text.AppendLiteral(name);
        text.AppendLiteral("(");
        Span<char> number = stackalloc char[NumAppend.MaxChars];
        bool separate = false;
        if (first is not null)
        {
            text.AppendLiteral(first);
            separate = true;
        }
        foreach (double value in values)
        {
            if (separate)
            {
                text.AppendLiteral(",");
            }
            text.AppendFormatted(number[..NumShortest.WriteRoundTrip(number, value)]);
            separate = true;
        }
        if (last is not null)
        {
            if (separate)
            {
                text.AppendLiteral(",");
            }
            text.AppendLiteral(last);
        }
        text.AppendLiteral(");");
        return text.ToStringAndClear();
    }

    /// <summary>
    /// Writes the text of <see cref="Call(string, ReadOnlySpan{double})"/> into <paramref name="destination"/> (at least
    /// <paramref name="name"/>'s length + 3 + <see cref="NumAppend.MaxChars"/> + 1 characters per value long) and returns its
    /// length: a compiler that quotes the instruction of every move in a comment writes it straight into the comment's line.
    /// </summary>
    internal static int WriteCall(Span<char> destination, string name, params ReadOnlySpan<double> values)
    {
        name.CopyTo(destination);
        int at = name.Length;
        destination[at++] = '(';
        for (int i = 0; i < values.Length; i++)
        {
            if (i > 0)
            {
                destination[at++] = ',';
            }
            at += NumShortest.WriteRoundTrip(destination[at..], values[i]);
        }
        destination[at++] = ')';
        destination[at++] = ';';
        return at;
    }

    /// <summary>
    /// A unit axis with the floating-point noise of rotation arithmetic removed (components within 1e-15 of 0 or ±1 become exactly
    /// that), so that <c>RotateTo(0,0,-1,0,1,0)</c> reads back as written instead of with <c>2.220446049250313E-16</c>. The
    /// rotation it describes changes by far less than the 1e-9 degrees within which instructions compare equal.
    /// </summary>
    internal static Vector Axis(Vector axis) => new(Unit(axis.X), Unit(axis.Y), Unit(axis.Z));

    private static double Unit(double value) =>
        Math.Abs(value) < 1e-15 ? 0 : Math.Abs(Math.Abs(value) - 1) < 1e-15 ? Math.Sign(value) : value;

    /// <summary>"Increase" or "Decrease" depending on the sign, as used by relative descriptions.</summary>
    internal static string Change(double value) => value < 0 ? "Decrease" : "Increase";
}
