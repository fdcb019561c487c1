namespace Machina.Simulation.UrScript;

/// <summary>Arithmetic (<c>+ - * / %</c>) and comparison (<c>== != &lt; &gt; &lt;= &gt;=</c>) of two values.</summary>
internal sealed class UrBinary(int line, string op, UrExpr left, UrExpr right) : UrExpr(line)
{
    /// <summary>The operator symbol.</summary>
    public string Op { get; } = op;

    /// <summary>The operator, looked up once (a switch on the symbol compares strings at every evaluation).</summary>
    private readonly Operator _op = op switch
    {
        "==" => Operator.Equal,
        "!=" => Operator.NotEqual,
        "+" => Operator.Add,
        "-" => Operator.Subtract,
        "*" => Operator.Multiply,
        "/" => Operator.Divide,
        "%" => Operator.Remainder,
        "<" => Operator.Less,
        ">" => Operator.Greater,
        "<=" => Operator.LessOrEqual,
        _ => Operator.GreaterOrEqual,
    };

    private enum Operator
    {
        Equal,
        NotEqual,
        Add,
        Subtract,
        Multiply,
        Divide,
        Remainder,
        Less,
        Greater,
        LessOrEqual,
        GreaterOrEqual,
    }

    /// <summary>The left operand.</summary>
    public UrExpr Left { get; } = left;

    /// <summary>The right operand.</summary>
    public UrExpr Right { get; } = right;

    /// <inheritdoc/>
    public override object Eval(UrFrame frame)
    {
        UrStack.Check(frame, Line);
        object a = Left.Eval(frame);
        object b = Right.Eval(frame);
        return Combine(a, b);
    }

    /// <inheritdoc/>
    public override double EvalNumber(UrFrame frame, int line, string what)
    {
        UrStack.Check(frame, Line);
        object a = Left.Eval(frame);
        object b = Right.Eval(frame);
        // Float arithmetic without boxing its result (a pose literal's elements): what Combine gives, as a double.
        if (_op is Operator.Add or Operator.Subtract or Operator.Multiply or Operator.Divide or Operator.Remainder
            && UrValue.IsNumber(a) && UrValue.IsNumber(b) && !(a is int && b is int))
        {
            return Arithmetic(UrValue.Number(a, Line, "an operand"), UrValue.Number(b, Line, "an operand"));
        }
        return UrValue.Number(Combine(a, b), line, what);
    }

    /// <summary>The operator applied to the operands' values.</summary>
    private object Combine(object a, object b)
    {
        switch (_op)
        {
            case Operator.Equal:
                return UrValue.Box(UrValue.AreEqual(a, b));
            case Operator.NotEqual:
                return UrValue.Box(!UrValue.AreEqual(a, b));
        }
        if (a is int x && b is int y)
        {
            return _op switch
            {
                Operator.Add => unchecked(x + y),
                Operator.Subtract => unchecked(x - y),
                Operator.Multiply => unchecked(x * y),
                Operator.Divide => y == 0 ? throw DivisionByZero() : (double)x / y,
                Operator.Remainder => y == 0 ? throw DivisionByZero() : y == -1 ? 0 : x % y, // -2147483648 % -1 would throw in .NET
                Operator.Less => UrValue.Box(x < y),
                Operator.Greater => UrValue.Box(x > y),
                Operator.LessOrEqual => UrValue.Box(x <= y),
                _ => UrValue.Box(x >= y),
            };
        }
        if ((a is UrList || b is UrList) && _op is Operator.Add or Operator.Subtract or Operator.Multiply or Operator.Divide or Operator.Remainder)
        {
            return ElementWise(a, b);
        }
        if (!UrValue.IsNumber(a) || !UrValue.IsNumber(b))
        {
            throw new UrRuntimeException(Line, $"'{Op}' cannot be applied to {UrValue.TypeName(a)} and {UrValue.TypeName(b)}");
        }
        double p = UrValue.Number(a, Line, "an operand"), q = UrValue.Number(b, Line, "an operand");
        return _op switch
        {
            Operator.Less => UrValue.Box(p < q),
            Operator.Greater => UrValue.Box(p > q),
            Operator.LessOrEqual => UrValue.Box(p <= q),
            Operator.GreaterOrEqual => UrValue.Box(p >= q),
            _ => Arithmetic(p, q),
        };
    }

    /// <summary><c>+ - * / %</c> on two floats.</summary>
    private double Arithmetic(double p, double q) => _op switch
    {
        Operator.Add => p + q,
        Operator.Subtract => p - q,
        Operator.Multiply => p * q,
        Operator.Divide => q == 0 ? throw DivisionByZero() : p / q,
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
        if (x is int i && y is int j && _op is Operator.Add or Operator.Subtract or Operator.Multiply)
        {
            return _op switch { Operator.Add => unchecked(i + j), Operator.Subtract => unchecked(i - j), _ => unchecked(i * j) };
        }
        return Arithmetic(UrValue.Number(x, Line, "an operand"), UrValue.Number(y, Line, "an operand"));
    }

    private UrRuntimeException DivisionByZero() => new(Line, "division by zero");
}
