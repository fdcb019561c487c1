namespace Machina.Simulation.Rapid;

/// <summary>Statements and expressions.</summary>
internal sealed partial class RapidParser
{
    private List<RapidStmt> Statements(params string[] ends)
    {
        Deeper();
        var list = new List<RapidStmt>();
        while (!IsAny(Peek, ends))
        {
            if (Peek.Kind == RapidTokenKind.End)
            {
                throw Error($"'{ends[^1]}' expected");
            }
            if (Peek.Kind == RapidTokenKind.Name && IsReserved(Peek.Text) && !StartsStatement(Peek.Text))
            {
                throw Error($"'{ends[^1]}' expected, found '{Peek.Text}'");
            }
            _operators = 0;
            list.Add(Statement());
        }
        _nesting--;
        return list;
    }

    private static bool IsAny(RapidToken token, string[] words)
    {
        if (token.Kind != RapidTokenKind.Name)
        {
            return false;
        }
        foreach (string w in words)
        {
            if (token.Is(w))
            {
                return true;
            }
        }
        return false;
    }

    private static bool StartsStatement(string word) => word.ToUpperInvariant() is "IF" or "WHILE" or "FOR" or "TEST" or "GOTO" or "RETURN"
        or "RAISE" or "RETRY" or "TRYNEXT" or "CONNECT";

    private RapidStmt Statement()
    {
        RapidToken head = Peek;
        if (head.IsSymbol("%"))
        {
            // Late binding: %expression% arguments; (the procedure is named by a string found when the statement runs).
            Next();
            RapidExpr procedure = Expression();
            Expect("%");
            RapidArg[] lateArgs = Peek.IsSymbol(";") ? [] : Arguments(";");
            Expect(";");
            return new RapidLateCall(head.Line, procedure, lateArgs);
        }
        if (head.Kind != RapidTokenKind.Name)
        {
            throw Error($"a statement expected, found '{head.Text}'");
        }
        int line = head.Line;
        switch (head.Text.ToUpperInvariant())
        {
            case "IF":
                return If();
            case "WHILE":
            {
                Next();
                RapidExpr condition = Expression();
                ExpectWord("DO");
                List<RapidStmt> body = Statements("ENDWHILE");
                Next();
                return new RapidWhile(line, condition, body);
            }
            case "FOR":
            {
                Next();
                string variable = Identifier("a loop variable");
                ExpectWord("FROM");
                RapidExpr from = Expression();
                ExpectWord("TO");
                RapidExpr to = Expression();
                RapidExpr? step = AcceptWord("STEP") ? Expression() : null;
                ExpectWord("DO");
                List<RapidStmt> body = Statements("ENDFOR");
                Next();
                return new RapidFor(line, variable, from, to, step, body);
            }
            case "TEST":
                return Test();
            case "GOTO":
            {
                Next();
                string label = Identifier("a label");
                Expect(";");
                return new RapidJump(line, RapidJumpKind.Goto, label);
            }
            case "RETURN":
            {
                Next();
                RapidExpr? value = Peek.IsSymbol(";") ? null : Expression();
                Expect(";");
                return new RapidJump(line, RapidJumpKind.Return, value: value);
            }
            case "RAISE":
            {
                Next();
                RapidExpr? value = Peek.IsSymbol(";") ? null : Expression();
                Expect(";");
                return new RapidJump(line, RapidJumpKind.Raise, value: value);
            }
            case "EXIT" or "STOP" or "RETRY" or "TRYNEXT":
            {
                Next();
                if (head.Is("STOP"))
                {
                    while (Accept("\\"))
                    {
                        Identifier("a switch");
                    }
                }
                Expect(";");
                RapidJumpKind kind = head.Text.ToUpperInvariant() switch
                {
                    "EXIT" => RapidJumpKind.Exit, "STOP" => RapidJumpKind.Stop, "RETRY" => RapidJumpKind.Retry, _ => RapidJumpKind.TryNext,
                };
                return new RapidJump(line, kind);
            }
            case "CONNECT":
            {
                Next();
                RapidExpr interrupt = Postfix(new RapidName(Peek.Line, Identifier("an interrupt variable")));
                ExpectWord("WITH");
                string trap = Identifier("a trap routine");
                Expect(";");
                return new RapidConnect(line, interrupt, trap);
            }
        }
        if (IsReserved(head.Text))
        {
            throw Error($"'{head.Text}' is not allowed here");
        }
        if (PeekAt(1).IsSymbol(":") && !PeekAt(1).IsSymbol(":="))
        {
            Next();
            Next();
            return new RapidJump(line, RapidJumpKind.Label, head.Text);
        }
        if (PeekAt(1).IsSymbol(":=") || PeekAt(1).IsSymbol(".") || PeekAt(1).IsSymbol("{"))
        {
            RapidExpr target = Postfix(new RapidName(line, Next().Text));
            Expect(":=");
            RapidExpr value = Expression();
            Expect(";");
            return new RapidAssign(line, target, value);
        }
        string name = Next().Text;
        RapidArg[] args = Peek.IsSymbol(";") ? [] : Arguments(";");
        Expect(";");
        return new RapidProcCall(line, name, args);
    }

    private RapidIf If()
    {
        int line = Next().Line;
        RapidExpr condition = Expression();
        if (!AcceptWord("THEN"))
        {
            RapidStmt single = Statement();
            return new RapidIf(line, [(condition, [single])], null);
        }
        var branches = new List<(RapidExpr, List<RapidStmt>)> { (condition, Statements("ELSEIF", "ELSE", "ENDIF")) };
        List<RapidStmt>? otherwise = null;
        while (true)
        {
            if (AcceptWord("ELSEIF"))
            {
                RapidExpr c = Expression();
                ExpectWord("THEN");
                branches.Add((c, Statements("ELSEIF", "ELSE", "ENDIF")));
            }
            else if (AcceptWord("ELSE"))
            {
                otherwise = Statements("ENDIF");
            }
            else
            {
                ExpectWord("ENDIF");
                return new RapidIf(line, branches, otherwise);
            }
        }
    }

    private RapidTest Test()
    {
        int line = Next().Line;
        RapidExpr value = Expression();
        var cases = new List<(RapidExpr[], List<RapidStmt>)>();
        List<RapidStmt>? otherwise = null;
        while (true)
        {
            if (AcceptWord("CASE"))
            {
                var values = new List<RapidExpr>();
                do
                {
                    values.Add(Expression());
                }
                while (Accept(","));
                Expect(":");
                cases.Add(([.. values], Statements("CASE", "DEFAULT", "ENDTEST")));
            }
            else if (AcceptWord("DEFAULT"))
            {
                Expect(":");
                otherwise = Statements("CASE", "DEFAULT", "ENDTEST");
            }
            else
            {
                ExpectWord("ENDTEST");
                return new RapidTest(line, value, cases, otherwise);
            }
        }
    }

    /// <summary>Arguments up to <paramref name="end"/>: positional ones separated by commas; <c>\Name:=value</c> and <c>\Switch</c> need no comma.</summary>
    private RapidArg[] Arguments(string end)
    {
        List<RapidArg> args = _spareArgs.Count > 0 ? _spareArgs.Pop() : [];
        while (true)
        {
            int line = Peek.Line;
            if (Accept("\\"))
            {
                string name = Identifier("an optional argument name");
                args.Add(new RapidArg(name, Accept(":=") ? Expression() : null, line));
            }
            else
            {
                args.Add(new RapidArg(null, Expression(), line));
            }
            if (Peek.IsSymbol(end))
            {
                RapidArg[] result = [.. args];
                args.Clear();
                _spareArgs.Push(args);
                return result;
            }
            if (!Accept(",") && !Peek.IsSymbol("\\"))
            {
                throw Error($"',' or '{end}' expected, found '{Peek.Text}'");
            }
        }
    }

    /// <summary>An expression: OR/XOR below AND below comparisons below + - below * / DIV MOD; NOT applies to a comparison.</summary>
    private RapidExpr Expression()
    {
        Deeper();
        RapidExpr left = And();
        while (Peek.Is("OR") || Peek.Is("XOR"))
        {
            RapidToken op = Next();
            Operator();
            left = new RapidBinary(op.Line, op.Text.ToUpperInvariant(), left, And());
        }
        _nesting--;
        return left;
    }

    private RapidExpr And()
    {
        RapidExpr left = Not();
        while (Peek.Is("AND"))
        {
            RapidToken op = Next();
            Operator();
            left = new RapidBinary(op.Line, "AND", left, Not());
        }
        return left;
    }

    private RapidExpr Not()
    {
        if (Peek.Is("NOT"))
        {
            RapidToken op = Next();
            Operator();
            Deeper();
            var not = new RapidUnary(op.Line, "NOT", Not());
            _nesting--;
            return not;
        }
        return Comparison();
    }

    private RapidExpr Comparison()
    {
        RapidExpr left = Sum();
        while (Peek.Kind == RapidTokenKind.Symbol && Peek.Text is "=" or "<>" or "<" or ">" or "<=" or ">=")
        {
            RapidToken op = Next();
            Operator();
            left = new RapidBinary(op.Line, op.Text, left, Sum());
        }
        return left;
    }

    private RapidExpr Sum()
    {
        RapidExpr left = Product();
        while (Peek.IsSymbol("+") || Peek.IsSymbol("-"))
        {
            RapidToken op = Next();
            Operator();
            left = new RapidBinary(op.Line, op.Text, left, Product());
        }
        return left;
    }

    private RapidExpr Product()
    {
        RapidExpr left = Unary();
        while (Peek.IsSymbol("*") || Peek.IsSymbol("/") || Peek.Is("DIV") || Peek.Is("MOD"))
        {
            RapidToken op = Next();
            Operator();
            left = new RapidBinary(op.Line, op.Text.ToUpperInvariant(), left, Unary());
        }
        return left;
    }

    private RapidExpr Unary()
    {
        if (Peek.IsSymbol("-") || Peek.IsSymbol("+"))
        {
            RapidToken op = Next();
            if (Peek.Kind == RapidTokenKind.Number && Peek.Number != 0)
            {
                // A signed number literal (-30 in a robtarget) is one literal, as its value and type are the same: one node fewer.
                RapidToken number = Next();
                return NumberLiteral(number.Line, op.Text == "-" ? -number.Number : number.Number);
            }
            Operator();
            Deeper();
            var sign = new RapidUnary(op.Line, op.Text, Unary());
            _nesting--;
            return sign;
        }
        return Primary();
    }

    private RapidExpr Primary()
    {
        RapidToken t = Next();
        switch (t.Kind)
        {
            case RapidTokenKind.Number:
                return NumberLiteral(t.Line, t.Number);
            case RapidTokenKind.String:
                return new RapidLiteral(t.Line, t.Text);
            case RapidTokenKind.Name when t.Is("TRUE") || t.Is("FALSE"):
                return new RapidLiteral(t.Line, t.Is("TRUE"));
            case RapidTokenKind.Name when !IsReserved(t.Text):
                if (Accept("("))
                {
                    Operator();
                    RapidArg[] args = Peek.IsSymbol(")") ? [] : Arguments(")");
                    Expect(")");
                    return Postfix(new RapidCallExpr(t.Line, t.Text, args));
                }
                return Postfix(new RapidName(t.Line, t.Text));
            case RapidTokenKind.Symbol when t.Text == "(":
            {
                RapidExpr inner = Expression();
                Expect(")");
                return Postfix(inner);
            }
            case RapidTokenKind.Symbol when t.Text == "[":
            {
                List<RapidExpr> items = _spareItems.Count > 0 ? _spareItems.Pop() : [];
                if (!Peek.IsSymbol("]"))
                {
                    do
                    {
                        items.Add(Expression());
                    }
                    while (Accept(","));
                }
                Expect("]");
                RapidExpr[] values = [.. items];
                items.Clear();
                _spareItems.Push(items);
                return Postfix(new RapidAggregate(t.Line, values));
            }
            default:
                throw Error($"an expression expected, found '{t.Text}'", t);
        }
    }

    private RapidExpr Postfix(RapidExpr target)
    {
        while (true)
        {
            if (Accept("."))
            {
                target = new RapidComponent(target.Line, target, Identifier("a component name"));
            }
            else if (Accept("{"))
            {
                var indices = new List<RapidExpr>();
                do
                {
                    indices.Add(Expression());
                }
                while (Accept(","));
                Expect("}");
                target = new RapidIndex(target.Line, target, [.. indices]);
            }
            else
            {
                return target;
            }
        }
    }
}
