using System.Globalization;
using System.Runtime.CompilerServices;
using System.Text;

namespace Machina;

/// <summary>The arguments of one statement being parsed, with typed accessors that report precise errors.</summary>
internal sealed class InstructionArgs
{
    internal struct Arg
    {
        internal int Start;
        internal int Length;
        internal int Line;
        internal int Column;
        internal bool Quoted;
        internal string? Text;

        /// <summary>True when the parser read the argument as a plain number already (<see cref="Number"/>).</summary>
        internal bool IsNumber;

        /// <summary>The value of a plain number, as <see cref="NumParse.TryParse"/> reads the argument's text.</summary>
        internal double Number;
    }

    private Arg[] _args = new Arg[20];
    private char[] _source = [];

    internal int Count { get; private set; }

    internal string Name { get; private set; } = "";

    internal int Line { get; private set; }

    internal int Column { get; private set; }

    internal void Begin(char[] source, string name, int line, int column)
    {
        _source = source;
        Name = name;
        Line = line;
        Column = column;
        Count = 0;
    }

    /// <summary>
    /// Adds an argument that starts at <paramref name="line"/> and <paramref name="column"/>, and returns it to be filled in
    /// place (the parser's path: no copy of the argument per value read).
    /// </summary>
    internal ref Arg Next(int line, int column)
    {
        if (Count == _args.Length)
        {
            Grow();
        }
        ref Arg arg = ref _args[Count++];
        arg = new Arg { Line = line, Column = column };
        return ref arg;
    }

    /// <summary>Adds a plain number read by the parser (<see cref="Arg.IsNumber"/>) at <paramref name="start"/> of the source.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    internal void AddNumber(int line, int column, int start, int length, double value)
    {
        if (Count == _args.Length)
        {
            Grow();
        }
        ref Arg arg = ref _args[Count++];
        arg.Start = start;
        arg.Length = length;
        arg.Line = line;
        arg.Column = column;
        arg.Quoted = false;
        arg.Text = null;
        arg.IsNumber = true;
        arg.Number = value;
    }

    /// <summary>Drops the arguments added since <see cref="Begin"/>, for the parser to read them again another way.</summary>
    internal void Drop() => Count = 0;

    private void Grow() => Array.Resize(ref _args, _args.Length * 2);

    private ReadOnlySpan<char> Raw(int i) => _source.AsSpan(_args[i].Start, _args[i].Length);

    private ReadOnlySpan<char> Value(int i) => _args[i].Quoted ? _args[i].Text.AsSpan() : Raw(i);

    private InstructionParseException Error(int i, string problem) => new(_args[i].Line, _args[i].Column, problem);

    /// <summary>Argument <paramref name="i"/> as a number.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    internal double D(int i)
    {
        ref Arg arg = ref _args[i];
        return arg.IsNumber ? arg.Number : ParseD(i);
    }

    /// <summary>Argument <paramref name="i"/> as a number, when the parser did not read it as a plain number.</summary>
    private double ParseD(int i)
    {
        // Quoted numbers ("12.5") are accepted because the original stripped quotes from every argument.
        if (NumParse.TryParse(Value(i), out double v) && double.IsFinite(v))
        {
            return v;
        }
        throw Error(i, $"argument {i + 1} of {Name} must be a number (like 12.5), but it is {Show(i)}.");
    }

    /// <summary>Argument <paramref name="i"/> as a whole number.</summary>
    internal long L(int i)
    {
        if (long.TryParse(Value(i), NumberStyles.AllowLeadingSign, CultureInfo.InvariantCulture, out long v))
        {
            return v;
        }
        throw Error(i, $"argument {i + 1} of {Name} must be a whole number (like 2000), but it is {Show(i)}.");
    }

    /// <summary>Argument <paramref name="i"/> as a 32-bit whole number.</summary>
    internal int I(int i)
    {
        long v = L(i);
        return v is >= int.MinValue and <= int.MaxValue ? (int)v : throw Error(i, $"argument {i + 1} of {Name} is too large.");
    }

    /// <summary>Argument <paramref name="i"/> as true/false (any letter case), or <paramref name="fallback"/> when absent.</summary>
    internal bool B(int i, bool fallback)
    {
        if (i >= Count)
        {
            return fallback;
        }
        ReadOnlySpan<char> s = Value(i);
        if (s.Equals("true", StringComparison.OrdinalIgnoreCase))
        {
            return true;
        }
        if (s.Equals("false", StringComparison.OrdinalIgnoreCase))
        {
            return false;
        }
        throw Error(i, $"argument {i + 1} of {Name} must be true or false, but it is {Show(i)}.");
    }

    /// <summary>Argument <paramref name="i"/> as text (quoted with escapes, or a bare word).</summary>
    internal string S(int i) => _args[i].Quoted ? _args[i].Text! : Raw(i).ToString();

    /// <summary>Argument <paramref name="i"/> as a member of <typeparamref name="T"/> (any letter case).</summary>
    internal T E<T>(int i, string what) where T : struct, Enum
    {
        string text = S(i);
        if (EnumText.TryParse<T>(text, out T value))
        {
            return value;
        }
        throw Error(i, $"\"{text}\" is not a valid {what}; use one of: {string.Join(", ", Enum.GetNames<T>())}.");
    }

    private string Show(int i) => _args[i].Quoted ? "the text \"" + _args[i].Text + "\"" : "\"" + Raw(i).ToString() + "\"";

    /// <summary>Resolves escapes in a quoted string: \" \\ \n \r \t \uXXXX; other backslashes are kept as they are.</summary>
    internal static string Unescape(ReadOnlySpan<char> body)
    {
        if (body.IndexOf('\\') < 0)
        {
            return body.ToString();
        }
        var sb = new StringBuilder(body.Length);
        for (int k = 0; k < body.Length; k++)
        {
            char c = body[k];
            if (c != '\\' || k + 1 >= body.Length)
            {
                sb.Append(c);
                continue;
            }
            char n = body[++k];
            switch (n)
            {
                case '"': sb.Append('"'); break;
                case '\\': sb.Append('\\'); break;
                case 'n': sb.Append('\n'); break;
                case 'r': sb.Append('\r'); break;
                case 't': sb.Append('\t'); break;
                case 'u' when k + 4 < body.Length && int.TryParse(body.Slice(k + 1, 4), NumberStyles.AllowHexSpecifier, CultureInfo.InvariantCulture, out int code):
                    sb.Append((char)code);
                    k += 4;
                    break;
                default: sb.Append('\\').Append(n); break;
            }
        }
        return sb.ToString();
    }
}
