using System.Globalization;
using System.Text;

namespace Machina.Simulation.Rapid;

/// <summary>A record value: its type and its components (double, bool, string, records, arrays).</summary>
internal sealed class RapidRecord(RapidType type, object[] fields)
{
    /// <summary>The record type.</summary>
    public RapidType Type { get; } = type;

    /// <summary>The components, in the order of the type.</summary>
    public object[] Fields { get; } = fields;
}

/// <summary>An array value (1 to 3 dimensions, 1-based indices), stored row by row.</summary>
internal sealed class RapidArray(int[] dimensions, object[] items)
{
    /// <summary>The size of each dimension.</summary>
    public int[] Dimensions { get; } = dimensions;

    /// <summary>The elements.</summary>
    public object[] Items { get; } = items;
}

/// <summary>Value helpers: defaults, copies (RAPID data are values: storing copies them), equality and text.</summary>
internal static class RapidValues
{
    /// <summary>The initial value of data of type <paramref name="type"/> with <paramref name="dimensions"/> (0, FALSE, "" and so on).</summary>
    public static object Default(RapidDataType type, int[]? dimensions = null)
    {
        if (type.Rank > 0)
        {
            int[] dims = dimensions ?? new int[type.Rank];
            int count = dims.Aggregate(1, (a, b) => a * b);
            var items = new object[count];
            for (int i = 0; i < count; i++)
            {
                items[i] = Default(new RapidDataType(type.Element));
            }
            return new RapidArray(dims, items);
        }
        RapidType t = type.Element;
        return t.Kind switch
        {
            RapidTypeKind.Num or RapidTypeKind.Dnum => RapidBoxes.Num(0),
            RapidTypeKind.Bool => RapidBoxes.Bool(false),
            RapidTypeKind.String => "",
            RapidTypeKind.Record => DefaultRecord(t),
            _ => t.Create?.Invoke() ?? new object(),
        };
    }

    /// <summary>A record of <paramref name="type"/> with each component's initial value (a plain loop: a routine's record locals are made at each call).</summary>
    private static RapidRecord DefaultRecord(RapidType type)
    {
        object?[] scalars = type.ScalarDefaults;
        var fields = new object[scalars.Length];
        for (int i = 0; i < fields.Length; i++)
        {
            fields[i] = scalars[i] ?? Default(type.Fields[i].Type);
        }
        return new RapidRecord(type, fields);
    }

    /// <summary>A copy of <paramref name="value"/>: records and arrays are copied deeply; non-value data are shared.</summary>
    public static object Copy(object value) => value switch
    {
        RapidRecord r => new RapidRecord(r.Type, r.Type.Flat ? Shared(r.Fields) : CopyAll(r.Fields)),
        RapidArray a => new RapidArray(a.Dimensions, HoldsScalars(a) ? Shared(a.Items) : CopyAll(a.Items)),
        _ => value,
    };

    /// <summary>
    /// True when the elements of <paramref name="array"/> are neither records nor arrays (an array's elements are all of one type, so
    /// its first tells): its copy shares them all, as <see cref="Copy"/> shares every number, string and non-value datum.
    /// </summary>
    private static bool HoldsScalars(RapidArray array) => array.Items.Length == 0 || array.Items[0] is not (RapidRecord or RapidArray);

    /// <summary>A new array of the same references: the copy of components <see cref="Copy"/> would share one by one (<c>values := NO_VALUES</c>).</summary>
    private static object[] Shared(object[] items)
    {
        var copy = new object[items.Length];
        items.AsSpan().CopyTo(copy);
        return copy;
    }

    /// <summary>Gives <paramref name="record"/>, which nothing else refers to, the initial value of its type in place (<see cref="DefaultRecord"/>'s value).</summary>
    public static void ResetToDefault(RapidRecord record)
    {
        object?[] scalars = record.Type.ScalarDefaults;
        object[] fields = record.Fields;
        for (int i = 0; i < fields.Length; i++)
        {
            if (scalars[i] is { } scalar)
            {
                fields[i] = scalar;
            }
            else if (fields[i] is RapidRecord nested && record.Type.Fields[i].Type is { Rank: 0 } type && nested.Type == type.Element)
            {
                ResetToDefault(nested);
            }
            else
            {
                fields[i] = Default(record.Type.Fields[i].Type);
            }
        }
    }

    /// <summary>
    /// Copies the components of <paramref name="from"/> into <paramref name="into"/>, a record of the same type that nothing else
    /// refers to (its nested records too, which are its own): the value <see cref="Copy"/> gives, without a new record.
    /// </summary>
    public static void CopyInto(RapidRecord into, RapidRecord from)
    {
        object[] target = into.Fields, source = from.Fields;
        if (from.Type.Flat)
        {
            source.AsSpan().CopyTo(target); // every component shared, as Copy would (r := requests{readIndex})
            return;
        }
        for (int i = 0; i < source.Length; i++)
        {
            object field = source[i];
            if (field is RapidRecord nested && target[i] is RapidRecord own && own.Type == nested.Type)
            {
                CopyInto(own, nested);
            }
            else
            {
                target[i] = Copy(field);
            }
        }
    }

    private static object[] CopyAll(object[] items)
    {
        var copy = new object[items.Length];
        for (int i = 0; i < items.Length; i++)
        {
            copy[i] = Copy(items[i]);
        }
        return copy;
    }

    /// <summary>True when two values are equal (numbers exactly, records component by component).</summary>
    public static bool AreEqual(object a, object b) => (a, b) switch
    {
        (string x, string y) => string.Equals(x, y, StringComparison.Ordinal),
        (double x, double y) => x == y,
        (RapidRecord x, RapidRecord y) => x.Fields.Length == y.Fields.Length && x.Fields.Zip(y.Fields).All(p => AreEqual(p.First, p.Second)),
        (RapidArray x, RapidArray y) => x.Items.Length == y.Items.Length && x.Items.Zip(y.Items).All(p => AreEqual(p.First, p.Second)),
        _ => a.Equals(b),
    };

    /// <summary>
    /// True when <paramref name="a"/> and <paramref name="b"/> hold the same value to the bit (numbers by their bits: 0 and -0 differ,
    /// a NaN is its own), so that a copy of one may stand for the other; data that are not values are compared by reference.
    /// </summary>
    public static bool Identical(object a, object b)
    {
        // Tests of one value at a time, commonest first (a motion compares its tooldata and wobjdata, ~40 components, at every
        // move): the switch on the pair of values this replaces tested each case on both and cost ~8,800 instructions per move.
        // The same object first: a copy shares its numbers' boxes and its strings (Copy), so the kept copy of a tooldata that
        // was not assigned since holds the very boxes of the data it is compared with (values are never mutated in a box).
        if (ReferenceEquals(a, b))
        {
            return true;
        }
        if (a is double x)
        {
            return b is double y && BitConverter.DoubleToInt64Bits(x) == BitConverter.DoubleToInt64Bits(y);
        }
        if (a is RapidRecord r)
        {
            return b is RapidRecord q && r.Type == q.Type && AllIdentical(r.Fields, q.Fields);
        }
        if (a is string s)
        {
            return b is string t && string.Equals(s, t, StringComparison.Ordinal);
        }
        if (a is bool p)
        {
            return b is bool o && p == o;
        }
        if (a is RapidArray m)
        {
            return b is RapidArray n && m.Dimensions.AsSpan().SequenceEqual(n.Dimensions) && AllIdentical(m.Items, n.Items);
        }
        return ReferenceEquals(a, b);
    }

    private static bool AllIdentical(object[] a, object[] b)
    {
        if (a.Length != b.Length)
        {
            return false;
        }
        for (int i = 0; i < a.Length; i++)
        {
            // The same box or string (a kept copy shares its leaves with the data it was copied from): no call for it.
            if (!ReferenceEquals(a[i], b[i]) && !Identical(a[i], b[i]))
            {
                return false;
            }
        }
        return true;
    }

    /// <summary>A number as the controller writes it with <c>ValToStr</c>: up to 6 significant digits.</summary>
    public static string FormatNumber(double value)
    {
        if (value == Math.Round(value) && Math.Abs(value) < 1e7)
        {
            return value.ToString("0", CultureInfo.InvariantCulture);
        }
        return value.ToString("G6", CultureInfo.InvariantCulture).Replace("E+", "E", StringComparison.Ordinal);
    }

    /// <summary>A value as <c>ValToStr</c> writes it: numbers, <c>TRUE</c>/<c>FALSE</c>, quoted strings, <c>[…]</c> aggregates.</summary>
    public static string ToText(object value)
    {
        var text = new StringBuilder();
        Append(text, value, true);
        return text.ToString();
    }

    private static void Append(StringBuilder text, object value, bool top)
    {
        switch (value)
        {
            case double d:
                text.Append(FormatNumber(d));
                break;
            case bool b:
                text.Append(b ? "TRUE" : "FALSE");
                break;
            case string s:
                text.Append(top ? s : $"\"{s}\"");
                break;
            case RapidRecord r:
                AppendAll(text, r.Fields);
                break;
            case RapidArray a:
                AppendAll(text, a.Items);
                break;
            default:
                text.Append(value);
                break;
        }
    }

    private static void AppendAll(StringBuilder text, object[] items)
    {
        text.Append('[');
        for (int i = 0; i < items.Length; i++)
        {
            if (i > 0)
            {
                text.Append(',');
            }
            Append(text, items[i], false);
        }
        text.Append(']');
    }
}
