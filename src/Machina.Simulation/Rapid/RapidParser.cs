using Machina.Simulation.Twin;

namespace Machina.Simulation.Rapid;

/// <summary>
/// Parses a RAPID module (RAPID reference manual, "Basic elements" and "Modules"): <c>MODULE name(attributes)</c>, records,
/// data declarations, PROC/FUNC/TRAP routines with error handlers, up to <c>ENDMODULE</c>.
/// </summary>
internal sealed partial class RapidParser
{
    private static readonly string[] BodyEnds = ["ERROR", "BACKWARD", "UNDO", "ENDFUNC", "ENDTRAP", "ENDPROC"];

    // The lexer runs one token ahead of the parser: the grammar needs one token of lookahead, never more, and never goes back.
    private readonly RapidLexer _lexer;
    private RapidToken _current;
    private RapidToken _following;

    private readonly TwinLimits _limits;

    /// <summary>How deep the parser is in brackets, signs and blocks (bounded by <see cref="TwinLimits.MaxNesting"/>).</summary>
    private int _nesting;

    /// <summary>The operators and calls of the statement or declaration being read (bounded by <see cref="TwinLimits.MaxExpressionOperators"/>).</summary>
    private int _operators;

    private RapidParser(string text, TwinLimits limits)
    {
        _limits = limits;
        _lexer = new RapidLexer(text);
        _current = _lexer.Next();
        _following = _lexer.Next();
    }

    // One boxed value per number: a compiled module repeats the same few numbers (0, 1, 9E9…) hundreds of thousands of times.
    private readonly Dictionary<double, object> _numbers = [];

    // The number literals of the line being read (see NumberLiteral).
    private readonly Dictionary<double, RapidLiteral> _lineLiterals = [];
    private int _literalLine = -1;

    // Lists for the items of aggregates and the arguments of calls being read, kept for the next ones (one per nesting level).
    private readonly Stack<List<RapidExpr>> _spareItems = new();
    private readonly Stack<List<RapidArg>> _spareArgs = new();

    /// <summary>Parses one module within <paramref name="limits"/> (the default ones when null); throws <see cref="RapidLoadException"/> at the first syntax error.</summary>
    public static RapidModule Parse(string text, TwinLimits? limits = null)
    {
        limits ??= TwinLimits.Default;
        if (text.Length > limits.MaxProgramChars)
        {
            throw new RapidLoadException(1, RapidLoadException.Syntax($"the module is longer than {limits.MaxProgramChars} characters (the twin's limit)"));
        }
        return new RapidParser(text, limits).Module();
    }

    /// <summary>One level deeper (a bracket, a sign, a block): past the budget the module is refused.</summary>
    private void Deeper()
    {
        if (++_nesting > _limits.MaxNesting)
        {
            throw Error($"the module is nested more than {_limits.MaxNesting} levels deep (brackets, signs and blocks)");
        }
    }

    /// <summary>One operator or call more in the statement: past the budget the module is refused.</summary>
    private void Operator()
    {
        if (++_operators > _limits.MaxExpressionOperators)
        {
            throw Error($"the statement has more than {_limits.MaxExpressionOperators} operators and calls");
        }
    }

    private ref readonly RapidToken Peek => ref _current;

    private RapidToken PeekAt(int ahead) => ahead == 0 ? _current : _following;

    private RapidToken Next()
    {
        RapidToken token = _current;
        Advance();
        return token;
    }

    private object Boxed(double number)
    {
        if (!_numbers.TryGetValue(number, out object? boxed))
        {
            boxed = number;
            if (_numbers.Count < 4096)
            {
                _numbers[number] = boxed;
            }
        }
        return boxed;
    }

    /// <summary>
    /// A number literal, one node per value and line: a compiled robtarget repeats 0, 1 and 9E9 on its line, and a literal's
    /// type (num) and line (for a refusal) are the same wherever it stands on that line.
    /// </summary>
    private RapidLiteral NumberLiteral(int line, double value)
    {
        if (line != _literalLine)
        {
            _lineLiterals.Clear();
            _literalLine = line;
        }
        if (!_lineLiterals.TryGetValue(value, out RapidLiteral? literal))
        {
            literal = new RapidLiteral(line, Boxed(value));
            _lineLiterals[value] = literal;
        }
        return literal;
    }

    private void Advance()
    {
        if (_current.Kind != RapidTokenKind.End)
        {
            _current = _following;
            _following = _following.Kind == RapidTokenKind.End ? _following : _lexer.Next();
        }
    }

    private RapidLoadException Error(string what, RapidToken? at = null) =>
        new((at ?? Peek).Line, RapidLoadException.Syntax(what));

    private RapidToken Expect(string symbol)
    {
        if (!Peek.IsSymbol(symbol))
        {
            throw Error($"'{symbol}' expected, found '{Peek.Text}'");
        }
        return Next();
    }

    private RapidToken ExpectWord(string word)
    {
        if (!Peek.Is(word))
        {
            throw Error($"'{word}' expected, found '{Peek.Text}'");
        }
        return Next();
    }

    private string Identifier(string what)
    {
        if (Peek.Kind != RapidTokenKind.Name || IsReserved(Peek.Text))
        {
            throw Error($"{what} expected, found '{Peek.Text}'");
        }
        return Next().Text;
    }

    private bool Accept(string symbol)
    {
        if (Peek.IsSymbol(symbol))
        {
            Advance();
            return true;
        }
        return false;
    }

    private bool AcceptWord(string word)
    {
        if (Peek.Is(word))
        {
            Advance();
            return true;
        }
        return false;
    }

    private RapidModule Module()
    {
        int line = ExpectWord("MODULE").Line;
        string name = Identifier("a module name");
        var attributes = new List<string>();
        if (Accept("("))
        {
            do
            {
                attributes.Add(Identifier("a module attribute").ToUpperInvariant());
            }
            while (Accept(","));
            Expect(")");
        }
        var module = new RapidModule(line, name, attributes);
        while (!Peek.Is("ENDMODULE"))
        {
            if (Peek.Kind == RapidTokenKind.End)
            {
                throw Error("'ENDMODULE' expected");
            }
            ModuleItem(module);
        }
        Next();
        if (Peek.Kind != RapidTokenKind.End)
        {
            throw Error($"nothing may follow ENDMODULE, found '{Peek.Text}'");
        }
        return module;
    }

    private void ModuleItem(RapidModule module)
    {
        bool local = AcceptWord("LOCAL");
        bool task = !local && AcceptWord("TASK");
        RapidToken head = Peek;
        if (head.Is("RECORD"))
        {
            Next();
            string name = Identifier("a record name");
            var fields = new List<(string, string)>();
            while (!AcceptWord("ENDRECORD"))
            {
                string type = Identifier("a component type");
                fields.Add((type, Identifier("a component name")));
                Expect(";");
            }
            module.Records.Add(new RapidRecordDecl(head.Line, name, fields));
        }
        else if (head.Is("PROC") || head.Is("FUNC") || head.Is("TRAP"))
        {
            RapidRoutine routine = Routine(local);
            routine.Module = module;
            module.Routines.Add(routine);
        }
        else if (head.Is("VAR") || head.Is("CONST") || head.Is("PERS"))
        {
            module.Data.Add(DataDecl(local));
        }
        else if (head.Is("ALIAS"))
        {
            throw Error("ALIAS declarations are not supported by the twin");
        }
        else
        {
            throw Error($"a declaration expected, found '{head.Text}'{(task ? " after TASK" : "")}");
        }
    }

    private RapidDataDecl DataDecl(bool local)
    {
        _operators = 0;
        RapidToken head = Next();
        RapidStorage storage = head.Is("CONST") ? RapidStorage.Const : head.Is("PERS") ? RapidStorage.Pers : RapidStorage.Var;
        string type = Identifier("a data type");
        string name = Identifier("a data name");
        var dims = new List<RapidExpr>();
        if (Accept("{"))
        {
            do
            {
                dims.Add(Expression());
            }
            while (Accept(","));
            Expect("}");
        }
        RapidExpr? initial = null;
        if (Accept(":="))
        {
            initial = Expression();
        }
        else if (storage == RapidStorage.Const)
        {
            throw Error($"the constant '{name}' needs a value (':=' expected)");
        }
        Expect(";");
        return new RapidDataDecl(head.Line, storage, type, name, [.. dims], initial, local);
    }

    private RapidRoutine Routine(bool local)
    {
        RapidToken head = Next();
        RapidRoutineKind kind = head.Is("PROC") ? RapidRoutineKind.Proc : head.Is("FUNC") ? RapidRoutineKind.Func : RapidRoutineKind.Trap;
        string? returnType = kind == RapidRoutineKind.Func ? Identifier("the type the function returns") : null;
        string name = Identifier("a routine name");
        var parameters = new List<RapidParam>();
        if (kind != RapidRoutineKind.Trap)
        {
            Expect("(");
            if (!Peek.IsSymbol(")"))
            {
                do
                {
                    Parameters(parameters);
                }
                while (Accept(",") || Peek.IsSymbol("\\"));
            }
            Expect(")");
        }
        var routine = new RapidRoutine(head.Line, kind, name, returnType, parameters, local);
        while (Peek.Is("VAR") || Peek.Is("CONST") || Peek.Is("PERS"))
        {
            routine.Data.Add(DataDecl(false));
        }
        routine.Body.AddRange(Statements(BodyEnds));
        if (AcceptWord("ERROR"))
        {
            if (Accept("("))
            {
                routine.ErrorList = [];
                do
                {
                    routine.ErrorList.Add(Expression());
                }
                while (Accept(","));
                Expect(")");
            }
            routine.ErrorHandler = Statements(BodyEnds);
        }
        if (AcceptWord("UNDO"))
        {
            routine.UndoHandler = Statements(BodyEnds);
        }
        if (Peek.Is("BACKWARD"))
        {
            throw Error("BACKWARD handlers are not supported by the twin");
        }
        string end = kind switch { RapidRoutineKind.Proc => "ENDPROC", RapidRoutineKind.Func => "ENDFUNC", _ => "ENDTRAP" };
        ExpectWord(end);
        return routine;
    }

    private void Parameters(List<RapidParam> parameters)
    {
        bool optional = Accept("\\");
        do
        {
            RapidParamMode mode = AcceptWord("VAR") ? RapidParamMode.Var : AcceptWord("PERS") ? RapidParamMode.Pers
                : AcceptWord("INOUT") ? RapidParamMode.InOut : RapidParamMode.In;
            string type = Identifier("a parameter type");
            string name = Identifier("a parameter name");
            int rank = 0;
            if (Accept("{"))
            {
                do
                {
                    Expect("*");
                    rank++;
                }
                while (Accept(","));
                Expect("}");
            }
            parameters.Add(new RapidParam(name, type, mode, optional, rank));
        }
        while (optional && Accept("|"));
    }

    private static readonly HashSet<string> Reserved = new(
    [
        "AND", "OR", "XOR", "NOT", "DIV", "MOD", "IF", "THEN", "ELSE", "ELSEIF", "ENDIF", "WHILE", "DO", "ENDWHILE", "FOR", "FROM", "TO", "STEP",
        "ENDFOR", "TEST", "CASE", "DEFAULT", "ENDTEST", "GOTO", "RETURN", "RETRY", "TRYNEXT", "RAISE", "ERROR", "ENDPROC", "ENDFUNC", "ENDTRAP",
        "ENDMODULE", "MODULE", "PROC", "FUNC", "TRAP", "VAR", "CONST", "PERS", "LOCAL", "TASK", "RECORD", "ENDRECORD", "CONNECT", "WITH", "INOUT",
        "BACKWARD", "UNDO", "ALIAS", "TRUE", "FALSE",
    ], StringComparer.OrdinalIgnoreCase);

    private static bool IsReserved(string word) => Reserved.Contains(word);
}
