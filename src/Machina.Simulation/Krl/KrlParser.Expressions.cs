using System.Globalization;

namespace Machina.Simulation.Krl;

/// <summary>
/// KRL expressions. Priority from strongest to weakest, as the KSS manual orders them: NOT B_NOT and the sign; * /; + -;
/// AND B_AND; EXOR B_EXOR; OR B_OR; the comparisons == &lt;&gt; &lt; &lt;= &gt; &gt;=. There is no MOD.
/// </summary>
internal sealed partial class KrlParser
{
    private static readonly string[][] Levels =
    [
        ["==", "<>", "<", "<=", ">", ">="],
        ["OR", "B_OR"],
        ["EXOR", "B_EXOR"],
        ["AND", "B_AND"],
        ["+", "-"],
        ["*", "/"],
    ];

    private KrlExpr Expression()
    {
        if (_expressions++ == 0)
        {
            _operators = 0;
        }
        Deeper();
        KrlExpr expr = Binary(0);
        _nesting--;
        _expressions--;
        return expr;
    }

    private KrlExpr Binary(int level)
    {
        if (level == Levels.Length)
        {
            return Unary();
        }
        KrlExpr left = Binary(level + 1);
        while (Operator(Levels[level]) is string op)
        {
            int line = Peek.Line;
            _at++;
            Operator();
            left = new KrlBinary(line, op, left, Binary(level + 1));
        }
        return left;
    }

    private string? Operator(string[] ops)
    {
        KrlToken token = Peek;
        if (token.Kind is not (KrlTokenKind.Symbol or KrlTokenKind.Name))
        {
            return null;
        }
        foreach (string op in ops)
        {
            if (token.IsSymbol(op) || token.Is(op))
            {
                return op;
            }
        }
        return null;
    }

    private KrlExpr Unary()
    {
        KrlToken token = Peek;
        if (token.Is("NOT") || token.Is("B_NOT") || token.IsSymbol("-") || token.IsSymbol("+"))
        {
            _at++;
            Operator();
            Deeper();
            KrlExpr operand = Unary();
            _nesting--;
            if (token.IsSymbol("+"))
            {
                return operand;
            }
            if (token.IsSymbol("-") && operand is KrlLiteral { Value: int i })
            {
                return new KrlLiteral(token.Line, -i);
            }
            if (token.IsSymbol("-") && operand is KrlLiteral { Value: double d })
            {
                return new KrlLiteral(token.Line, -d);
            }
            return new KrlUnary(token.Line, token.Text.ToUpperInvariant(), operand);
        }
        return Postfix();
    }

    private KrlExpr Postfix()
    {
        KrlExpr expr = Primary();
        while (true)
        {
            KrlToken token = Peek;
            if (token.IsSymbol("(") && expr is KrlName name && name.Cell is null)
            {
                _at++;
                Operator();
                var arguments = new List<KrlExpr>();
                if (!Peek.IsSymbol(")"))
                {
                    do
                    {
                        // An argument left out (MsgNotify(text[], "INFO", , value[])): the parameter is not given a value.
                        arguments.Add(Peek.IsSymbol(",") || Peek.IsSymbol(")") ? new KrlOmitted(Peek.Line) : Expression());
                    }
                    while (Accept(","));
                }
                Expect(")");
                expr = new KrlCall(token.Line, name.Name, arguments);
            }
            else if (token.IsSymbol("["))
            {
                _at++;
                var indices = new List<KrlExpr?>();
                if (!Peek.IsSymbol("]"))
                {
                    do
                    {
                        indices.Add(Peek.IsSymbol(",") || Peek.IsSymbol("]") ? null : Expression());
                    }
                    while (Accept(","));
                }
                Expect("]");
                expr = new KrlIndex(token.Line, expr, indices);
            }
            else if (token.IsSymbol("."))
            {
                _at++;
                expr = new KrlMember(token.Line, expr, Component());
            }
            else
            {
                return expr;
            }
        }
    }

    private KrlExpr Primary()
    {
        KrlToken token = Peek;
        _at++;
        switch (token.Kind)
        {
            case KrlTokenKind.Int:
                return int.TryParse(token.Text, NumberStyles.Integer, CultureInfo.InvariantCulture, out int whole)
                    ? new KrlLiteral(token.Line, whole)
                    : throw Error(token, $"the INT {token.Text} is out of range (-2147483648 to 2147483647)");
            case KrlTokenKind.Real:
                return double.TryParse(token.Text, NumberStyles.Float, CultureInfo.InvariantCulture, out double real) && double.IsFinite(real)
                    ? new KrlLiteral(token.Line, real)
                    : throw Error(token, $"{token.Display} is not a REAL number");
            case KrlTokenKind.String:
                return new KrlLiteral(token.Line, token.Text);
            case KrlTokenKind.Enum:
                return new KrlLiteral(token.Line, new KrlEnumValue(token.Text));
            case KrlTokenKind.Name when token.Is("TRUE") || token.Is("FALSE"):
                return new KrlLiteral(token.Line, token.Is("TRUE"));
            case KrlTokenKind.Name when !KrlKeywords.IsReserved(token.Text):
                return new KrlName(token.Line, token.Text);
            case KrlTokenKind.Symbol when token.Text == "(":
            {
                KrlExpr inner = Expression();
                Expect(")");
                return inner;
            }
            case KrlTokenKind.Symbol when token.Text == "{":
                return Aggregate(token);
            default:
                _at--;
                throw Error(token, $"expected a value, found {token.Display}");
        }
    }

    private KrlAggregate Aggregate(KrlToken open)
    {
        string? typeName = null;
        if (Peek.Kind == KrlTokenKind.Name && PeekAt(1).IsSymbol(":"))
        {
            typeName = Peek.Text;
            _at += 2;
        }
        var fields = new List<(string, KrlExpr)>();
        if (!Peek.IsSymbol("}"))
        {
            do
            {
                string field = Component();
                if (Peek.IsSymbol("["))
                {
                    _at++;
                    Expect("]");
                }
                fields.Add((field, Expression()));
            }
            while (Accept(","));
        }
        Expect("}");
        return new KrlAggregate(open.Line, typeName, fields);
    }
}
