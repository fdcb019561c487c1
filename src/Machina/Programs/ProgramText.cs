using System.Runtime.CompilerServices;
using System.Buffers;

namespace Machina;

/// <summary>Text helpers shared by the program compilers: one-line texts and exact seconds.</summary>
internal static class ProgramText
{
    /// <summary>True for characters that end a line or are invisible controls: C0/C1 controls, DEL and the Unicode line and paragraph separators.</summary>
    internal static bool BreaksLine(char c) => char.IsControl(c) || c is '\u2028' or '\u2029';

    /// <summary>Characters that break a line or are invisible controls: <see cref="char.IsControl(char)"/>, U+2028 and U+2029.</summary>
    private static readonly SearchValues<char> LineBreakers = SearchValues.Create(Characters((0, 0x1f), (0x7f, 0x9f), (0x2028, 0x2029)));

    /// <summary>The characters robot-language comments replace: C0 controls, DEL, NEL (U+0085), U+2028 and U+2029.</summary>
    private static readonly SearchValues<char> CommentBreakers = SearchValues.Create(Characters((0, 0x1f), (0x7f, 0x7f), (0x85, 0x85), (0x2028, 0x2029)));

    /// <summary>
    /// The characters of the inclusive ranges, in order. A loop, not LINQ: these tables are made once in every process that
    /// compiles, and LINQ's iterators over <c>int</c> and <c>char</c> were some thirty methods the JIT compiled for them.
    /// </summary>
    private static char[] Characters(params (int First, int Last)[] ranges)
    {
        int count = 0;
        foreach ((int first, int last) in ranges)
        {
            count += last - first + 1;
        }
        char[] characters = new char[count];
        int at = 0;
        foreach ((int first, int last) in ranges)
        {
            for (int c = first; c <= last; c++)
            {
                characters[at++] = (char)c;
            }
        }
        return characters;
    }

    /// <summary>The text on one line: every character that breaks a line or is a control character becomes a space.</summary>
    internal static string OneLine(string text) => Replace(text, LineBreakers);

    /// <summary>A text safe inside a one-line RAPID or URScript comment: line breaks and control characters become spaces.</summary>
    internal static string CommentText(string text) => Replace(text, CommentBreakers);

    /// <summary>The text with every character of <paramref name="breakers"/> replaced by a space; the same string when there is none.</summary>
    private static string Replace(string text, SearchValues<char> breakers)
    {
        int first = text.AsSpan().IndexOfAny(breakers);
        if (first < 0)
        {
            return text;
        }
        return string.Create(text.Length, (text, breakers, first), static (span, state) =>
        {
            state.text.AsSpan().CopyTo(span);
            for (int i = state.first; i < span.Length; i++)
            {
                if (state.breakers.Contains(span[i]))
                {
                    span[i] = ' ';
                }
            }
        });
    }

    /// <summary>
    /// Appends the action's description (<see cref="RobotAction.Describe"/>) safe inside a one-line comment: as
    /// <see cref="CommentText"/>, or as <see cref="OneLine"/> with <paramref name="oneLine"/>. A move's or a turn's description
    /// (digits and fixed words only, <see cref="RobotAction.TryWriteDescription"/>) is written straight into the line, without a
    /// string in between.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    internal static System.Text.StringBuilder AppendDescription(this System.Text.StringBuilder sb, RobotAction action, bool oneLine = false)
    {
        Span<char> buffer = stackalloc char[RobotAction.MaxWrittenDescriptionChars];
        int written = action.TryWriteDescription(buffer);
        if (written >= 0)
        {
            return sb.Append(buffer[..written]);
        }
        string text = action.Describe();
        return sb.Append(oneLine ? OneLine(text) : CommentText(text));
    }

    /// <summary>Milliseconds as exact decimal seconds, never in exponent form: 1500 → "1.5", 1 → "0.001", 0 → "0".</summary>
    internal static string Seconds(long millis)
    {
        long whole = Math.DivRem(millis, 1000, out long rest);
        string text = whole.ToString(Num.Inv);
        return rest == 0 ? text : text + "." + rest.ToString("000", Num.Inv).TrimEnd('0');
    }
}
