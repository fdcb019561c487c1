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
        if (!UrValue.IsNumber(a) || !UrValue.IsNumber(b))
        {
            throw new UrRuntimeException(Line, $"'{Op}' cannot be applied to {UrValue.TypeName(a)} and {UrValue.TypeName(b)}");
        }
        double p = UrValue.Number(a, Line, "an operand"), q = UrValue.Number(b, Line, "an operand");
        return Op switch
        {
            "+" => p + q,
            "-" => p - q,
            "*" => p * q,
            "/" => q == 0 ? throw DivisionByZero() : p / q,
            "%" => q == 0 ? throw DivisionByZero() : p % q,
            "<" => UrValue.Box(p < q),
            ">" => UrValue.Box(p > q),
            "<=" => UrValue.Box(p <= q),
            _ => UrValue.Box(p >= q),
        };
    }

    private UrRuntimeException DivisionByZero() => new(Line, "division by zero");
}
