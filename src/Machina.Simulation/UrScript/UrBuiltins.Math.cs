using System.Globalization;

namespace Machina.Simulation.UrScript;

internal static partial class UrBuiltins
{
    private static void AddMath(Dictionary<string, UrBuiltin> t)
    {
        Unary(t, "sin", Math.Sin);
        Unary(t, "cos", Math.Cos);
        Unary(t, "tan", Math.Tan);
        Unary(t, "asin", x => Domain(Math.Asin(x), "asin"));
        Unary(t, "acos", x => Domain(Math.Acos(x), "acos"));
        Unary(t, "atan", Math.Atan);
        Unary(t, "sqrt", x => x < 0 ? throw new ArgumentOutOfRangeException(nameof(x), "sqrt of a negative number") : Math.Sqrt(x));
        Unary(t, "d2r", x => x * Math.PI / 180);
        Unary(t, "r2d", x => x * 180 / Math.PI);
        Add(t, "atan2", (m, line, a) => Math.Atan2(Num(a, 0, line, "atan2", "y"), Num(a, 1, line, "atan2", "x")), R("y"), R("x"));
        Add(t, "pow", (m, line, a) => Math.Pow(Num(a, 0, line, "pow", "base"), Num(a, 1, line, "pow", "exponent")), R("base"), R("exponent"));
        Add(t, "log", (m, line, a) => Math.Log(Num(a, 1, line, "log", "f"), Num(a, 0, line, "log", "b")), R("b"), R("f"));
        Add(t, "floor", (m, line, a) => (int)Math.Floor(Num(a, 0, line, "floor", "f")), R("f"));
        Add(t, "ceil", (m, line, a) => (int)Math.Ceiling(Num(a, 0, line, "ceil", "f")), R("f"));
        Add(t, "round", (m, line, a) => (int)Math.Round(Num(a, 0, line, "round", "f"), MidpointRounding.AwayFromZero), R("f"));
        Add(t, "norm", (m, line, a) => a[0] switch
        {
            int i => Math.Abs(i),
            double d => Math.Abs(d),
            UrPose p => Math.Sqrt(p.Values.Sum(v => v * v)),
            UrList l => Math.Sqrt(l.Items.Sum(v => Math.Pow(UrValue.Number(v, line, "norm: an element"), 2))),
            _ => throw new UrRuntimeException(line, $"norm: cannot take the norm of {UrValue.TypeName(a[0])}"),
        }, R("a"));
        Add(t, "length", (m, line, a) => a[0] switch
        {
            UrList l => l.Items.Length,
            UrPose => 6,
            string s => s.Length,
            _ => throw new UrRuntimeException(line, $"length: {UrValue.TypeName(a[0])} has no length"),
        }, R("v"));
        Add(t, "to_str", (m, line, a) => UrValue.ToText(a[0], UrValue.TextLength(a[0]), m.Limits.MaxStringLength, line, "to_str"), R("val"));
        Add(t, "str_cat", (m, line, a) => UrValue.ToText(a[0], UrValue.TextLength(a[0]) + UrValue.TextLength(a[1]), m.Limits.MaxStringLength, line, "str_cat")
            + UrValue.ToText(a[1]), R("op1"), R("op2"));
        Add(t, "str_len", (m, line, a) => Str(a, 0, line, "str_len", "str").Length, R("str"));
        Add(t, "str_find", (m, line, a) =>
        {
            string s = Str(a, 0, line, "str_find", "s1"), target = Str(a, 1, line, "str_find", "s2");
            int start = Int(a, 2, line, "str_find", "start_from");
            return start < 0 || start > s.Length ? -1 : s.IndexOf(target, start, StringComparison.Ordinal);
        }, R("s1"), R("s2"), O("start_from", 0));
        Add(t, "str_sub", (m, line, a) =>
        {
            string s = Str(a, 0, line, "str_sub", "src");
            int index = Int(a, 1, line, "str_sub", "index"), len = Int(a, 2, line, "str_sub", "len");
            if (index < 0 || index > s.Length)
            {
                throw new UrRuntimeException(line, $"str_sub: index {index} is outside the string");
            }
            return len <= 0 ? s[index..] : s.Substring(index, Math.Min(len, s.Length - index));
        }, R("src"), R("index"), O("len", 0));
        Add(t, "to_num", (m, line, a) =>
        {
            string s = Str(a, 0, line, "to_num", "str").Trim();
            if (int.TryParse(s, NumberStyles.Integer, CultureInfo.InvariantCulture, out int i))
            {
                return i;
            }
            return double.TryParse(s, NumberStyles.Float, CultureInfo.InvariantCulture, out double d)
                ? d
                : throw new UrRuntimeException(line, $"to_num: \"{s}\" is not a number");
        }, R("str"));
        Add(t, "random", (m, line, a) => m.Controller.Random.NextDouble());
        Add(t, "binary_list_to_integer", (m, line, a) =>
        {
            object[] bits = a[0] is UrList l ? l.Items : throw new UrRuntimeException(line, "binary_list_to_integer: needs a list of bools");
            int value = 0;
            for (int i = Math.Min(bits.Length, 31) - 1; i >= 0; i--)
            {
                value = (value << 1) | (UrValue.Bool(bits[i], line, "binary_list_to_integer: an element") ? 1 : 0);
            }
            return value;
        }, R("l"));
        Add(t, "integer_to_binary_list", (m, line, a) =>
        {
            int x = Int(a, 0, line, "integer_to_binary_list", "x");
            return new UrList([.. Enumerable.Range(0, 32).Select(i => UrValue.Box(((x >> i) & 1) == 1))]);
        }, R("x"));
    }

    private static double Domain(double value, string name) =>
        double.IsNaN(value) ? throw new ArgumentOutOfRangeException(name, $"{name} of a number outside -1 to 1") : value;

    private static void Unary(Dictionary<string, UrBuiltin> t, string name, Func<double, double> f) =>
        Add(t, name, (m, line, a) =>
        {
            try
            {
                return f(Num(a, 0, line, name, "f"));
            }
            catch (ArgumentOutOfRangeException e)
            {
                throw new UrRuntimeException(line, $"{name}: {e.Message.Split(" (Parameter", 2)[0]}");
            }
        }, R("f"));
}
