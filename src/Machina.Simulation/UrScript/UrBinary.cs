namespace Machina.Simulation.UrScript;

/// <summary>Arithmetic (<c>+ - * / %</c>) and comparison (<c>== != &lt; &gt; &lt;= &gt;=</c>) of two values.</summary>
internal sealed class UrBinary(int line, string op, UrExpr left, UrExpr right) : UrExpr(line)
{
    /// <summary>The operator symbol.</summary>
    public string Op { get; } = op;

    /// <summary>The left operand.</summary>
    public UrExpr Left { get; } = left;

    /// <summary>The right operand.</summary>
    public UrExpr Right { get; } = right;

    /// <inheritdoc/>
    public override object Eval(UrFrame frame)
    {
        UrStack.Check(Line);
        object a = Left.Eval(frame);
        object b = Right.Eval(frame);
        switch (Op)
        {
            case "==":
                return UrValue.Box(UrValue.AreEqual(a, b));
            case "!=":
                return UrValue.Box(!UrValue.AreEqual(a, b));
        }
        if (a is int x && b is int y)
        {
            return Op switch
            {
                "+" => unchecked(x + y),
                "-" => unchecked(x - y),
                "*" => unchecked(x * y),
                "/" => y == 0 ? throw DivisionByZero() : (double)x / y,
                "%" => y == 0 ? throw DivisionByZero() : y == -1 ? 0 : x % y, // -2147483648 % -1 would throw in .NET
                "<" => UrValue.Box(x < y),
                ">" => UrValue.Box(x > y),
                "<=" => UrValue.Box(x <= y),
                _ => UrValue.Box(x >= y),
            };
        }
        if ((a is UrList || b is UrList) && Op is "+" or "-" or "*" or "/" or "%")
        {
            return ElementWise(a, b);
        }
        if (!UrValue.IsNumber(a) || !UrValue.IsNumber(b))
        {
            throw new UrRuntimeException(Line, $"'{Op}' cannot be applied to {UrValue.TypeName(a)} and {UrValue.TypeName(b)}");
        }
        double p = UrValue.Number(a, Line, "an operand"), q = UrValue.Number(b, Line, "an operand");
        return Op switch
        {
            "<" => UrValue.Box(p < q),
            ">" => UrValue.Box(p > q),
            "<=" => UrValue.Box(p <= q),
            ">=" => UrValue.Box(p >= q),
            _ => Arithmetic(p, q),
        };
    }

    /// <summary><c>+ - * / %</c> on two floats.</summary>
    private double Arithmetic(double p, double q) => Op switch
    {
        "+" => p + q,
        "-" => p - q,
        "*" => p * q,
        "/" => q == 0 ? throw DivisionByZero() : p / q,
        _ => q == 0 ? throw DivisionByZero() : p % q,
    };

    /// <summary>
    /// Arithmetic on arrays, element by element (the Script Manual's array operations, which UR's clients use for joint
    /// vectors): two arrays of the same length, or an array and a number applied to every element.
    /// </summary>
    private UrList ElementWise(object a, object b)
    {
        UrList? left = a as UrList, right = b as UrList;
        if (left is not null && right is not null && left.Items.Length != right.Items.Length)
        {
            throw new UrRuntimeException(Line, $"'{Op}' needs arrays of the same length, not {left.Items.Length} and {right.Items.Length}");
        }
        int n = (left ?? right)!.Items.Length;
        var items = new object[n];
        for (int i = 0; i < n; i++)
        {
            object x = left is null ? a : left.Items[i], y = right is null ? b : right.Items[i];
            items[i] = Apply(x, y);
        }
        return new UrList(items);
    }

    /// <summary>The operator on two elements (numbers, or arrays nested in arrays).</summary>
    private object Apply(object x, object y)
    {
        if (x is UrList || y is UrList)
        {
            return ElementWise(x, y);
        }
        if (!UrValue.IsNumber(x) || !UrValue.IsNumber(y))
        {
            throw new UrRuntimeException(Line, $"'{Op}' cannot be applied to {UrValue.TypeName(x)} and {UrValue.TypeName(y)} in an array");
        }
        if (x is int i && y is int j && Op is "+" or "-" or "*")
        {
            return Op switch { "+" => unchecked(i + j), "-" => unchecked(i - j), _ => unchecked(i * j) };
        }
        return Arithmetic(UrValue.Number(x, Line, "an operand"), UrValue.Number(y, Line, "an operand"));
    }

    private UrRuntimeException DivisionByZero() => new(Line, "division by zero");
}
