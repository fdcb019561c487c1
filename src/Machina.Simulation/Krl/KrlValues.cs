using System.Globalization;
using System.Runtime.CompilerServices;
using System.Text;

namespace Machina.Simulation.Krl;

/// <summary>An enumeration value such as <c>#QUIT</c> (names compare without case).</summary>
/// <param name="Name">The name without the <c>#</c>.</param>
internal sealed record KrlEnumValue(string Name)
{
    /// <inheritdoc/>
    public bool Equals(KrlEnumValue? other) => other is not null && string.Equals(Name, other.Name, StringComparison.OrdinalIgnoreCase);

    /// <inheritdoc/>
    public override int GetHashCode() => StringComparer.OrdinalIgnoreCase.GetHashCode(Name);

    /// <inheritdoc/>
    public override string ToString() => "#" + Name;
}

/// <summary>An aggregate's value: the components it gives (the others keep the value of what it is assigned to).</summary>
/// <param name="Type">The structure type.</param>
/// <param name="Indexes">The components given.</param>
/// <param name="Values">Their values.</param>
internal sealed record KrlPartialValue(KrlType Type, int[] Indexes, object[] Values);

/// <summary>Making, copying and converting KRL values (boxed int, double, bool, char, enum, structure, array).</summary>
internal static partial class KrlValues
{
    private static readonly object[] SmallInts = [.. Enumerable.Range(-1, 4098).Select(i => (object)i)];
    private static readonly object[] Chars = [.. Enumerable.Range(0, 256).Select(i => (object)(char)i)];

    /// <summary>A boxed INT, shared for -1 to 4096 (array indices, ids, counters) so that loops do not allocate.</summary>
    public static object Box(int value) => value is >= -1 and <= 4096 ? SmallInts[value + 1] : value;

    /// <summary>A boxed BOOL, shared (conditions are evaluated on every statement an interrupt watches).</summary>
    public static object Box(bool value) => value ? True : False;

    private static readonly object True = true;
    private static readonly object False = false;
    private static readonly object ZeroReal = 0.0;

    /// <summary>A boxed CHAR, shared for the first 256 characters.</summary>
    public static object Box(char value) => value < 256 ? Chars[value] : value;

    /// <summary>The initial value of a variable of <paramref name="type"/> (0, FALSE, empty).</summary>
    public static object Default(KrlType type)
    {
        // The scalars' shared boxes (a box is never changed: a store replaces it), and plain loops: a routine's locals are made
        // at every call (the driver's FRAME, E6POS and E6AXIS locals, once per action).
        switch (type.Kind)
        {
            case KrlKind.Int:
                return Box(0);
            case KrlKind.Real:
                return ZeroReal;
            case KrlKind.Bool:
                return False;
            case KrlKind.Char:
                return Box('\0');
            case KrlKind.Enum:
                return new KrlEnumValue("");
            case KrlKind.Struct:
                // A structure of INT, REAL, BOOL and CHAR components (E6POS, E6AXIS, FRAME, EKI_STATUS: several an action) is all zeros.
                return KrlStructValue.Zero(type) ?? new KrlStructValue(type, DefaultComponents(type));
            default:
            {
                if (type.Element!.Kind == KrlKind.Real)
                {
                    return KrlArrayValue.Zero(type);
                }
                var items = new object[type.Length];
                for (int i = 0; i < items.Length; i++)
                {
                    items[i] = Default(type.Element!);
                }
                return new KrlArrayValue(type, items);
            }
        }
    }

    private static object[] DefaultComponents(KrlType type)
    {
        IReadOnlyList<(string Name, KrlType Type)> fields = type.Fields;
        var values = new object[fields.Count];
        for (int i = 0; i < values.Length; i++)
        {
            values[i] = Default(fields[i].Type);
        }
        return values;
    }

    /// <summary>A copy of a value (structures and arrays deep, the rest as is).</summary>
    public static object Copy(object value) => value switch
    {
        KrlStructValue s => s.Copy(),
        KrlArrayValue a => a.Copy(),
        _ => value,
    };

    /// <summary>A number as REAL.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static double ToReal(object value) => value is double d ? d : IntToReal(value);

    /// <summary>An INT as REAL (the rest of <see cref="ToReal"/>, out of line: a REAL is the usual case and inlines).</summary>
    private static double IntToReal(object value) => value is int i ? i : throw new InvalidCastException($"{value} is not a number");

    /// <summary>A number as INT: a REAL is rounded to the nearest whole number, as KRL assigns REAL to INT.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static int ToInt(object value) => value is int i ? i : RealToInt(value);

    /// <summary>A REAL as INT (the rest of <see cref="ToInt"/>, out of line: an INT is the usual case and inlines).</summary>
    private static int RealToInt(object value) => value is double d
        ? (int)Math.Round(d, MidpointRounding.AwayFromZero)
        : throw new InvalidCastException($"{value} is not a number");

    /// <summary>The text of a CHAR array: its characters up to the first unset one.</summary>
    public static string Text(KrlArrayValue array)
    {
        object[] items = array.Objects;
        var text = new StringBuilder(items.Length);
        foreach (object item in items)
        {
            char c = (char)item;
            if (c == '\0')
            {
                break;
            }
            text.Append(c);
        }
        return text.ToString();
    }

    /// <summary>A value as the trace and messages write it.</summary>
    public static string Format(object value) => value switch
    {
        bool b => b ? "TRUE" : "FALSE",
        double d => d.ToString("0.######", CultureInfo.InvariantCulture),
        int i => i.ToString(CultureInfo.InvariantCulture),
        char c => c.ToString(),
        KrlArrayValue a when a.Type.Element!.Kind == KrlKind.Char => "\"" + Text(a) + "\"",
        KrlStructValue s => "{" + string.Join(", ", s.Type.Fields.Select((f, i) => f.Name + " " + Format(s.Values[i]))) + "}",
        _ => value.ToString() ?? "",
    };
}
