using System.Globalization;
using System.Text;

namespace Machina.Simulation.UrScript;

/// <summary>A URScript pose: x, y, z in metres and a rotation vector in radians (<c>p[x, y, z, rx, ry, rz]</c>).</summary>
internal sealed class UrPose(double[] values)
{
    /// <summary>The six numbers (the array is owned by the pose; an index assignment changes it).</summary>
    public double[] Values { get; } = values;

    /// <inheritdoc/>
    public override string ToString() => "p" + UrValue.FormatNumbers(Values);
}

/// <summary>A URScript list (array): a fixed-length sequence of values.</summary>
internal sealed class UrList(object[] items)
{
    /// <summary>The elements (an index assignment changes them).</summary>
    public object[] Items { get; } = items;

    /// <inheritdoc/>
    public override string ToString() => "[" + string.Join(", ", Items.Select(UrValue.ToText)) + "]";
}

/// <summary>Operations on URScript values: boxed int, double, bool, string, <see cref="UrList"/> and <see cref="UrPose"/>.</summary>
internal static class UrValue
{
    private static readonly object TrueBox = true;
    private static readonly object FalseBox = false;

    /// <summary>A boxed boolean without allocation.</summary>
    public static object Box(bool value) => value ? TrueBox : FalseBox;

    /// <summary>The boxes of the ints −1 to 254 (counts, codes, flags: what a socket read gives most), made once; a box is never written.</summary>
    private static readonly object[] SmallInts = [.. Enumerable.Range(-1, 256).Select(i => (object)i)];

    /// <summary>A boxed int; without allocation from −1 to 254.</summary>
    public static object Box(int value) => (uint)(value + 1) < (uint)SmallInts.Length ? SmallInts[value + 1] : value;

    /// <summary>An int or a float as a double.</summary>
    private static double AsDouble(object number) => number is int i ? i : (double)number;

    /// <summary>The name of a value's type, as in a URScript error message.</summary>
    public static string TypeName(object? value) => value switch
    {
        int => "int",
        double => "float",
        bool => "bool",
        string => "string",
        UrPose => "pose",
        UrList => "array",
        _ => "none",
    };

    /// <summary>True for an int or a float.</summary>
    public static bool IsNumber(object? value) => value is int or double;

    /// <summary>The number as a double, or a runtime error naming <paramref name="what"/>.</summary>
    public static double Number(object? value, int line, string what) => value switch
    {
        int i => i,
        double d => d,
        _ => throw new UrRuntimeException(line, $"{what} must be a number, not {TypeName(value)}"),
    };

    /// <summary>The number as an int (floats are truncated), or a runtime error.</summary>
    public static int Int(object? value, int line, string what) => value switch
    {
        int i => i,
        double d when double.IsFinite(d) && Math.Abs(d) < int.MaxValue => (int)d,
        _ => throw new UrRuntimeException(line, $"{what} must be an integer, not {TypeName(value)}"),
    };

    /// <summary>The value as a bool (numbers: non-zero is True), or a runtime error.</summary>
    public static bool Bool(object? value, int line, string what) => value switch
    {
        bool b => b,
        int i => i != 0,
        double d => d != 0,
        _ => throw new UrRuntimeException(line, $"{what} must be a bool, not {TypeName(value)}"),
    };

    /// <summary>The value as a string, or a runtime error.</summary>
    public static string Text(object? value, int line, string what) =>
        value as string ?? throw new UrRuntimeException(line, $"{what} must be a string, not {TypeName(value)}");

    /// <summary>Six numbers from a pose or a list of six numbers, or a runtime error.</summary>
    public static double[] Six(object? value, int line, string what)
    {
        if (value is UrPose pose)
        {
            return pose.Values;
        }
        if (value is UrList list && list.Items.Length == 6 && list.Items.All(IsNumber))
        {
            var six = new double[6];
            for (int k = 0; k < 6; k++)
            {
                six[k] = Number(list.Items[k], line, what);
            }
            return six;
        }
        throw new UrRuntimeException(line, $"{what} must be a pose or a list of 6 numbers, not {Describe(value)}");
    }

    /// <summary>The value as a pose (a list of six numbers is accepted, as the controller does), or a runtime error.</summary>
    public static UrPose Pose(object? value, int line, string what) => value as UrPose ?? new UrPose((double[])Six(value, line, what).Clone());

    /// <summary>A short description of a value for an error message.</summary>
    public static string Describe(object? value) => value is UrList l ? $"an array of {l.Items.Length}" : TypeName(value);

    /// <summary>The text textmsg, to_str and str_cat show for a value.</summary>
    public static string ToText(object? value) => value switch
    {
        null => "None",
        bool b => b ? "True" : "False",
        int i => i.ToString(CultureInfo.InvariantCulture),
        double d => FormatNumber(d),
        string s => s,
        _ => value.ToString() ?? "",
    };

    /// <summary>An upper bound of the length of <see cref="ToText(object?)"/> of <paramref name="value"/>, without building it.</summary>
    public static long TextLength(object? value) => value switch
    {
        string s => s.Length,
        UrList list => 2 + list.Items.Sum(item => TextLength(item) + 2),
        UrPose => 6 * 32,
        _ => 32,
    };

    /// <summary>
    /// <see cref="ToText(object?)"/> of <paramref name="value"/> when <paramref name="length"/> (the text <paramref name="function"/>
    /// builds) stays within <paramref name="most"/> characters; the program's error otherwise.
    /// </summary>
    public static string ToText(object? value, long length, int most, int line, string function) => length <= most
        ? ToText(value)
        : throw new UrRuntimeException(line, $"{function}: the string would be longer than {most} characters (the twin's limit)");

    /// <summary>A float as the controller prints it (up to 6 decimals).</summary>
    public static string FormatNumber(double d) => d.ToString("0.######", CultureInfo.InvariantCulture);

    /// <summary>Numbers as <c>[a, b, c]</c>.</summary>
    public static string FormatNumbers(IEnumerable<double> values)
    {
        var text = new StringBuilder("[");
        foreach (double v in values)
        {
            text.Append(text.Length > 1 ? ", " : "").Append(FormatNumber(v));
        }
        return text.Append(']').ToString();
    }

    /// <summary>URScript equality: numbers by value (2 == 2.0), strings and bools exactly, poses and lists element by element.</summary>
    public static bool AreEqual(object? a, object? b)
    {
        if (a is int i && b is int j)
        {
            return i == j; // as doubles: every int is one exactly
        }
        if (IsNumber(a) && IsNumber(b))
        {
            return AsDouble(a!) == AsDouble(b!);
        }
        return (a, b) switch
        {
            (bool x, bool y) => x == y,
            (string x, string y) => x == y,
            (UrPose x, UrPose y) => x.Values.AsSpan().SequenceEqual(y.Values),
            (UrList x, UrList y) => x.Items.Length == y.Items.Length && x.Items.Zip(y.Items).All(p => AreEqual(p.First, p.Second)),
            _ => false,
        };
    }
}

/// <summary>The value of a call to a function that returns nothing.</summary>
internal sealed class UrNone
{
    /// <summary>The one none value.</summary>
    public static readonly UrNone Value = new();

    private UrNone()
    {
    }

    /// <inheritdoc/>
    public override string ToString() => "None";
}
