using Machina.Simulation.Twin;

namespace Machina.Simulation.UrScript;

/// <summary>A parsed program: its functions and threads (nested ones too) and the statements outside any definition.</summary>
internal sealed class UrSyntaxTree
{
    /// <summary>Every def and thread, in text order.</summary>
    public List<UrFunction> Functions { get; } = [];

    /// <summary>The definitions at column 1 (not nested), in text order.</summary>
    public List<UrFunction> TopLevel { get; } = [];

    /// <summary>Statements outside any definition (for example the call of the program's def).</summary>
    public List<UrStmt> Statements { get; } = [];
}

/// <summary><c>global a, b</c> or <c>local a = 1</c>: declares the scope of names in a function.</summary>
internal sealed class UrDecl(int line, bool isGlobal, string name, UrAssign? initial) : UrStmt(line)
{
    /// <summary>True for global, false for local.</summary>
    public bool IsGlobal { get; } = isGlobal;

    /// <summary>The declared name.</summary>
    public string Name { get; } = name;

    /// <summary>The assignment written with the declaration, if any.</summary>
    public UrAssign? Initial { get; } = initial;

    /// <inheritdoc/>
    public override UrFlow Exec(UrFrame frame) => Initial?.Exec(frame) ?? UrFlow.Next;
}

/// <summary>Recursive-descent parser of URScript (the language of UR's Script Manual) into statements and expressions with lines.</summary>
internal sealed class UrParser
{
    private readonly UrTokenWindow _tokens;
    private readonly UrSyntaxTree _tree = new();

    /// <summary>The value of each literal met (text, negated), boxed once: a long program repeats few numbers.</summary>
    private readonly Dictionary<(string Text, bool Negate), object> _literals = [];
    private readonly TwinLimits _limits;
    private int _at;
    private int _depth;

    /// <summary>How deep the parser is in brackets, signs and blocks (bounded by <see cref="TwinLimits.MaxNesting"/>).</summary>
    private int _nesting;

    /// <summary>The operators and calls of the statement being read (bounded by <see cref="TwinLimits.MaxExpressionOperators"/>).</summary>
    private int _operators;

    private UrParser(UrTokenWindow tokens, TwinLimits limits)
    {
        _tokens = tokens;
        _limits = limits;
    }

    /// <summary>Parses a whole program within <paramref name="limits"/> (the default ones when null).</summary>
    /// <exception cref="UrCompileException">A syntax error, with its line.</exception>
    public static UrSyntaxTree Parse(string text, TwinLimits? limits = null)
    {
        var parser = new UrParser(new UrTokenWindow(UrLexer.Tokens(text)), limits ?? TwinLimits.Default);
        parser.SkipNewlines();
        while (parser.Peek.Kind != UrTokenKind.End)
        {
            UrStmt? statement = parser.Statement();
            if (statement is not null and not UrNoOp)
            {
                parser._tree.Statements.Add(statement);
            }
            parser.SkipNewlines();
        }
        return parser._tree;
    }

    private UrToken Peek => _tokens[_at];

    /// <summary>One level deeper (a bracket, a sign, a block): past the budget the program is refused.</summary>
    private void Deeper()
    {
        if (++_nesting > _limits.MaxNesting)
        {
            throw new UrCompileException(Peek.Line, $"the program is nested more than {_limits.MaxNesting} levels deep (brackets, signs and blocks)");
        }
    }

    /// <summary>One operator or call more in the statement: past the budget the program is refused.</summary>
    private void Operator(int line)
    {
        if (++_operators > _limits.MaxExpressionOperators)
        {
            throw new UrCompileException(line, $"the statement has more than {_limits.MaxExpressionOperators} operators and calls");
        }
    }

    private UrToken Next() => _tokens[_at++];

    private void SkipNewlines()
    {
        while (Peek.Kind == UrTokenKind.Newline)
        {
            _at++;
        }
    }

    private UrToken Expect(string symbol)
    {
        UrToken token = Peek;
        if (!token.Is(symbol))
        {
            throw new UrCompileException(token.Line, $"expected '{symbol}' but found {Show(token)}");
        }
        return Next();
    }

    private string ExpectName()
    {
        UrToken token = Peek;
        if (token.Kind != UrTokenKind.Name || IsKeyword(token.Text))
        {
            throw new UrCompileException(token.Line, $"expected a name but found {Show(token)}");
        }
        return Next().Text;
    }

    private void EndOfLine()
    {
        UrToken token = Peek;
        if (token.Kind != UrTokenKind.Newline)
        {
            throw new UrCompileException(token.Line, $"unexpected {Show(token)} at the end of the statement");
        }
        SkipNewlines();
    }

    /// <summary>
    /// The end of an assignment: a line end, or the next statement on the same line. ur_rtde's control script relies on it: it
    /// writes <c>global reg_offset_float = # comment</c>, then puts the value at the start of the next line, before that line's
    /// own statement (<c>0    global reg_offset_int = …</c>), and controllers run it.
    /// </summary>
    private void EndOfAssignment()
    {
        if (Peek.Kind != UrTokenKind.Name)
        {
            EndOfLine();
        }
    }

    private static string Show(UrToken token) => token.Kind switch
    {
        UrTokenKind.Newline => "the end of the line",
        UrTokenKind.End => "the end of the program",
        UrTokenKind.String => $"\"{token.Text}\"",
        _ => $"'{token.Text}'",
    };

    private static bool IsKeyword(string name) => name is "def" or "sec" or "thread" or "end" or "if" or "elif" or "else" or "while" or "return"
        or "break" or "continue" or "and" or "or" or "not" or "global" or "local" or "run" or "join" or "kill" or "halt" or "True" or "False";

    /// <summary>Statements up to (not including) one of the closing keywords.</summary>
    private List<UrStmt> Block(params string[] closers)
    {
        Deeper();
        var block = new List<UrStmt>();
        SkipNewlines();
        while (!(Peek.Kind == UrTokenKind.Name && closers.Contains(Peek.Text)))
        {
            if (Peek.Kind == UrTokenKind.End)
            {
                throw new UrCompileException(Peek.Line, $"'{closers[0]}' is missing before the end of the program");
            }
            UrStmt? statement = Statement();
            if (statement is not null)
            {
                block.Add(statement);
            }
            SkipNewlines();
        }
        _nesting--;
        return block;
    }

    private UrStmt? Statement()
    {
        _operators = 0;
        UrToken token = Peek;
        int line = token.Line;
        if (token.Kind == UrTokenKind.Name)
        {
            switch (token.Text)
            {
                case "def":
                case "sec":
                case "thread":
                    Definition();
                    return new UrNoOp(line);
                case "if":
                    return If();
                case "while":
                {
                    Next();
                    UrExpr condition = Expression();
                    Expect(":");
                    List<UrStmt> body = Block("end");
                    Next();
                    EndOfLine();
                    return new UrWhile(line, condition, body);
                }
                case "return":
                {
                    Next();
                    UrExpr? value = Peek.Kind == UrTokenKind.Newline ? null : Expression();
                    EndOfLine();
                    return new UrJump(line, UrFlow.Return, value);
                }
                case "break":
                case "continue":
                    Next();
                    EndOfLine();
                    return new UrJump(line, token.Text == "break" ? UrFlow.Break : UrFlow.Continue, null);
                case "halt":
                    Next();
                    EndOfLine();
                    return new UrHalt(line);
                case "join":
                case "kill":
                {
                    Next();
                    UrExpr handle = Expression();
                    EndOfLine();
                    return new UrThreadControl(line, token.Text == "kill", handle);
                }
                case "global":
                case "local":
                {
                    Next();
                    string name = ExpectName();
                    UrAssign? initial = null;
                    if (Peek.Is("="))
                    {
                        Next();
                        initial = new UrAssign(line, new UrName(line, name), Expression());
                        EndOfAssignment();
                    }
                    else
                    {
                        EndOfLine();
                    }
                    return new UrDecl(line, token.Text == "global", name, initial);
                }
                case "end":
                case "elif":
                case "else":
                    throw new UrCompileException(line, $"'{token.Text}' without a matching opening statement");
            }
        }
        UrExpr expr = Expression();
        if (Peek.Is("="))
        {
            if (expr is not (UrName or UrIndex))
            {
                throw new UrCompileException(line, "only a variable or an element can be assigned");
            }
            Next();
            UrExpr value = Expression();
            EndOfAssignment();
            return new UrAssign(line, expr, value);
        }
        if (expr is not (UrCall or UrRunExpr))
        {
            throw new UrCompileException(line, "a statement must be an assignment or a call");
        }
        EndOfLine();
        return new UrExprStmt(line, expr);
    }

    private void Definition()
    {
        UrToken keyword = Next();
        bool isThread = keyword.Text == "thread";
        string name = ExpectName();
        Expect("(");
        var parameters = new List<string>();
        var defaults = new List<UrExpr?>();
        while (!Peek.Is(")"))
        {
            parameters.Add(ExpectName());
            defaults.Add(Peek.Is("=") ? DefaultValue() : null);
            if (!Peek.Is(")"))
            {
                Expect(",");
            }
        }
        Next();
        Expect(":");
        if (isThread && parameters.Count > 0)
        {
            throw new UrCompileException(keyword.Line, $"thread '{name}' cannot have parameters");
        }
        bool topLevel = _depth == 0;
        _depth++;
        List<UrStmt> body = Block("end");
        _depth--;
        Next();
        if (Peek.Kind != UrTokenKind.End)
        {
            EndOfLine();
        }
        var function = new UrFunction(keyword.Line, name, [.. parameters], [.. defaults], body, isThread)
        {
            IsSecondary = keyword.Text == "sec",
            IsProgram = topLevel && parameters.Count == 0 && !isThread,
        };
        _tree.Functions.Add(function);
        if (topLevel)
        {
            _tree.TopLevel.Add(function);
        }
    }

    private UrExpr DefaultValue()
    {
        Next();
        UrExpr value = Expression();
        if (value is not (UrConst or UrListExpr or UrPoseExpr))
        {
            throw new UrCompileException(value.Line, "a default parameter value must be a constant");
        }
        return value;
    }

    private UrIf If()
    {
        int line = Next().Line;
        var branches = new List<(UrExpr, List<UrStmt>)>();
        UrExpr condition = Expression();
        Expect(":");
        branches.Add((condition, Block("elif", "else", "end")));
        List<UrStmt>? otherwise = null;
        while (true)
        {
            UrToken closer = Next();
            if (closer.Text == "elif")
            {
                UrExpr c = Expression();
                Expect(":");
                branches.Add((c, Block("elif", "else", "end")));
            }
            else if (closer.Text == "else")
            {
                Expect(":");
                otherwise = Block("end");
            }
            else
            {
                break;
            }
        }
        EndOfLine();
        return new UrIf(line, branches, otherwise);
    }

    private UrExpr Expression()
    {
        Deeper();
        UrExpr expr = Or();
        _nesting--;
        return expr;
    }

    private UrExpr Or()
    {
        UrExpr left = And();
        while (Peek.Is("or"))
        {
            int line = Next().Line;
            Operator(line);
            left = new UrLogical(line, false, left, And());
        }
        return left;
    }

    private UrExpr And()
    {
        UrExpr left = Not();
        while (Peek.Is("and"))
        {
            int line = Next().Line;
            Operator(line);
            left = new UrLogical(line, true, left, Not());
        }
        return left;
    }

    private UrExpr Not()
    {
        if (Peek.Is("not"))
        {
            int line = Next().Line;
            Operator(line);
            Deeper();
            var not = new UrUnary(line, "not", Not());
            _nesting--;
            return not;
        }
        return Comparison();
    }

    private UrExpr Comparison()
    {
        UrExpr left = Additive();
        while (Peek.Kind == UrTokenKind.Symbol && Peek.Text is "==" or "!=" or "<" or ">" or "<=" or ">=")
        {
            UrToken op = Next();
            Operator(op.Line);
            left = new UrBinary(op.Line, op.Text, left, Additive());
        }
        return left;
    }

    private UrExpr Additive()
    {
        UrExpr left = Multiplicative();
        while (Peek.Kind == UrTokenKind.Symbol && Peek.Text is "+" or "-")
        {
            UrToken op = Next();
            Operator(op.Line);
            left = new UrBinary(op.Line, op.Text, left, Multiplicative());
        }
        return left;
    }

    private UrExpr Multiplicative()
    {
        UrExpr left = Unary();
        while (Peek.Kind == UrTokenKind.Symbol && Peek.Text is "*" or "/" or "%")
        {
            UrToken op = Next();
            Operator(op.Line);
            left = new UrBinary(op.Line, op.Text, left, Unary());
        }
        return left;
    }

    private UrExpr Unary()
    {
        if (Peek.Is("-"))
        {
            int line = Next().Line;
            if (Peek.Kind is UrTokenKind.Int or UrTokenKind.Float)
            {
                UrToken literal = Next();
                return Postfix(Literal(literal, negate: true));
            }
            Operator(line);
            Deeper();
            var minus = new UrUnary(line, "-", Unary());
            _nesting--;
            return minus;
        }
        if (Peek.Is("+"))
        {
            Operator(Next().Line);
            Deeper();
            UrExpr plus = Unary();
            _nesting--;
            return plus;
        }
        return Postfix(Primary());
    }

    private UrConst Literal(UrToken token, bool negate)
    {
        if (!_literals.TryGetValue((token.Text, negate), out object? boxed))
        {
            double value = negate ? -token.Number : token.Number;
            if (token.Kind == UrTokenKind.Float)
            {
                boxed = value;
            }
            else if (value > int.MaxValue || value < int.MinValue)
            {
                throw new UrCompileException(token.Line, $"the integer {token.Text} is out of range");
            }
            else
            {
                boxed = (int)value;
            }
            _literals[(token.Text, negate)] = boxed;
        }
        return new UrConst(token.Line, boxed);
    }

    private UrExpr Postfix(UrExpr expr)
    {
        while (Peek.Is("["))
        {
            int line = Next().Line;
            Operator(line);
            UrExpr index = Expression();
            Expect("]");
            expr = new UrIndex(line, expr, index);
        }
        return expr;
    }

    private UrExpr Primary()
    {
        UrToken token = Next();
        switch (token.Kind)
        {
            case UrTokenKind.Int:
            case UrTokenKind.Float:
                return Literal(token, negate: false);
            case UrTokenKind.String:
                return new UrConst(token.Line, token.Text);
            case UrTokenKind.Symbol when token.Text == "(":
            {
                UrExpr inner = Expression();
                if (Peek.Is(","))
                {
                    // python-urx sends set_payload(m, (x, y, z)): the Script Manual has lists and poses, no tuples.
                    throw new UrCompileException(token.Line, "expected ')' but found ',': URScript has no tuples, a list is written [a, b, c]");
                }
                Expect(")");
                return inner;
            }
            case UrTokenKind.Symbol when token.Text == "[":
                return new UrListExpr(token.Line, [.. Items("]")]);
            case UrTokenKind.Name:
                return NamePrimary(token);
        }
        throw new UrCompileException(token.Line, $"unexpected {Show(token)}");
    }

    private UrExpr NamePrimary(UrToken token)
    {
        switch (token.Text)
        {
            case "True":
                return new UrConst(token.Line, UrValue.Box(true));
            case "False":
                return new UrConst(token.Line, UrValue.Box(false));
            case "p" when Peek.Is("["):
            {
                Next();
                List<UrExpr> items = Items("]");
                if (items.Count == 1)
                {
                    // An element of a variable named p (ur_rtde's control script has scale_pose(p, factor): p[0] = p[0] * factor):
                    // a pose literal has six.
                    return new UrIndex(token.Line, new UrName(token.Line, "p"), items[0]);
                }
                if (items.Count != 6)
                {
                    throw new UrCompileException(token.Line, $"a pose needs 6 numbers, not {items.Count}");
                }
                return new UrPoseExpr(token.Line, [.. items]);
            }
            case "enter_critical" or "exit_critical" when !Peek.Is("("):
                // A statement of its own on a controller; the twin takes it as a call of its built-in of the same name.
                return new UrCall(token.Line, token.Text, [], []);
            case "run":
            {
                string name = ExpectName();
                Expect("(");
                Expect(")");
                return new UrRunExpr(token.Line, name);
            }
        }
        if (IsKeyword(token.Text))
        {
            throw new UrCompileException(token.Line, $"unexpected '{token.Text}'");
        }
        if (!Peek.Is("("))
        {
            return new UrName(token.Line, token.Text);
        }
        Next();
        Operator(token.Line);
        var positional = new List<UrExpr>();
        var named = new List<(string, UrExpr)>();
        while (!Peek.Is(")"))
        {
            if (Peek.Kind == UrTokenKind.Name && _tokens[_at + 1].Is("="))
            {
                string key = Next().Text;
                Next();
                named.Add((key, Expression()));
            }
            else if (named.Count > 0)
            {
                throw new UrCompileException(Peek.Line, "a positional argument cannot follow a named one");
            }
            else
            {
                positional.Add(Expression());
            }
            if (!Peek.Is(")"))
            {
                Expect(",");
            }
        }
        Next();
        return new UrCall(token.Line, token.Text, positional, named);
    }

    private List<UrExpr> Items(string closer)
    {
        var items = new List<UrExpr>();
        while (!Peek.Is(closer))
        {
            items.Add(Expression());
            if (!Peek.Is(closer))
            {
                Expect(",");
            }
        }
        Next();
        return items;
    }
}
