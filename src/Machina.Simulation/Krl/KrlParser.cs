using System.Globalization;
using Machina.Simulation.Twin;

namespace Machina.Simulation.Krl;

/// <summary>
/// Reads a KRL file into a module: a <c>.src</c> file's DEF subprograms and DEFFCT functions (the first one is the file's main
/// routine) or a <c>.dat</c> file's DEFDAT data list. A syntax error refuses the file with its line.
/// </summary>
internal sealed partial class KrlParser
{
    private readonly string _file;
    private readonly List<KrlToken> _tokens;
    private readonly TwinLimits _limits;
    private int _at;

    /// <summary>How deep the parser is in brackets, signs and blocks (bounded by <see cref="TwinLimits.MaxNesting"/>).</summary>
    private int _nesting;

    /// <summary>How deep the parser is in expressions: the operators are counted from the outermost one.</summary>
    private int _expressions;

    /// <summary>The operators and calls of the expression being read (bounded by <see cref="TwinLimits.MaxExpressionOperators"/>).</summary>
    private int _operators;

    /// <summary>The array elements the file's declarations hold (bounded by <see cref="TwinLimits.MaxTotalElements"/>).</summary>
    private long _elements;

    /// <summary>Stops the reading of a long file (checked at each line).</summary>
    private readonly CancellationToken _cancellation;

    /// <summary>The program's own STRUC and ENUM types (see <see cref="KrlUserTypes"/>), or null.</summary>
    private IReadOnlyDictionary<string, KrlType>? _userTypes;

    private KrlParser(string file, string text, TwinLimits? limits, CancellationToken cancellation)
    {
        _cancellation = cancellation;
        _file = file;
        _limits = limits ?? TwinLimits.Default;
        if (text.Length > _limits.MaxProgramChars)
        {
            throw new KrlLoadException(file, 1, $"the file is longer than {_limits.MaxProgramChars} characters (the twin's limit)");
        }
        _tokens = KrlLexer.Tokenize(file, text, cancellation);
    }

    /// <summary>The value of an INT token; one past the INT range refuses the file.</summary>
    private int Whole(KrlToken token) => int.TryParse(token.Text, NumberStyles.Integer, CultureInfo.InvariantCulture, out int value)
        ? value
        : throw Error(token, $"the INT {token.Text} is out of range (-2147483648 to 2147483647)");

    /// <summary>One level deeper (a bracket, a sign, a block): past the budget the file is refused.</summary>
    private void Deeper()
    {
        if (++_nesting > _limits.MaxNesting)
        {
            throw Error(Peek, $"the file is nested more than {_limits.MaxNesting} levels deep (brackets, signs and blocks)");
        }
    }

    /// <summary>One operator or call more in the expression: past the budget the file is refused.</summary>
    private void Operator()
    {
        if (++_operators > _limits.MaxExpressionOperators)
        {
            throw Error(Peek, $"the expression has more than {_limits.MaxExpressionOperators} operators and calls");
        }
    }

    private KrlToken Peek => _tokens[_at];

    private KrlToken PeekAt(int ahead) => _tokens[Math.Min(_at + ahead, _tokens.Count - 1)];

    /// <summary>Reads the routines of a <c>.src</c> file into <paramref name="module"/> (until <paramref name="cancellation"/>, checked at each line).</summary>
    public static void ParseSource(string file, string text, KrlModule module, TwinLimits? limits = null, IReadOnlyDictionary<string, KrlType>? types = null, CancellationToken cancellation = default)
    {
        var parser = new KrlParser(file, text, limits, cancellation) { _externals = module.Externals, _userTypes = types };
        parser.SkipLines();
        bool first = true;
        while (parser.Peek.Kind != KrlTokenKind.End)
        {
            module.Routines.Add(parser.Routine(module.Name, first));
            first = false;
            parser.SkipLines();
        }
        if (first)
        {
            throw new KrlLoadException(file, 1, "the file has no DEF or DEFFCT");
        }
    }

    /// <summary>Reads the DEFDAT data list of a <c>.dat</c> file; returns its declarations for the binder (until <paramref name="cancellation"/>).</summary>
    public static KrlDataList ParseData(string file, string text, TwinLimits? limits = null, IReadOnlyDictionary<string, KrlType>? types = null, CancellationToken cancellation = default)
    {
        var parser = new KrlParser(file, text, limits, cancellation) { _userTypes = types };
        parser.SkipLines();
        KrlToken start = parser.Expect("DEFDAT");
        string name = parser.Identifier("the data list's name");
        bool isPublic = false;
        if (parser.Peek.Is("PUBLIC"))
        {
            parser._at++;
            isPublic = true;
        }
        parser.EndOfLine();
        var list = new KrlDataList(file, name, isPublic, start.Line);
        parser._externals = list.Externals;
        while (!parser.Peek.Is("ENDDAT"))
        {
            if (parser.Peek.Kind == KrlTokenKind.End)
            {
                throw parser.Error(parser.Peek, "ENDDAT is missing");
            }
            if (parser.Peek.Is("SIGNAL"))
            {
                throw parser.Error(parser.Peek, "SIGNAL declarations belong in $CONFIG.DAT; the twin takes signals from its options");
            }
            if (parser.IsElementInitialiser())
            {
                list.Elements.Add(parser.ElementInitialiser());
                continue;
            }
            list.Declarations.AddRange(parser.Declaration(allowInitial: true));
        }
        parser._at++;
        parser.EndOfLine();
        parser.SkipLines();
        if (parser.Peek.Kind != KrlTokenKind.End)
        {
            throw parser.Error(parser.Peek, $"unexpected {parser.Peek.Display} after ENDDAT");
        }
        return list;
    }

    private KrlRoutine Routine(string module, bool first)
    {
        bool global = false;
        if (Peek.Is("GLOBAL"))
        {
            _at++;
            global = true;
        }
        KrlToken def = Peek;
        KrlType? returns = null;
        if (def.Is("DEFFCT"))
        {
            _at++;
            returns = TypeName();
            if (returns.Kind == KrlKind.Char && Accept("["))
            {
                // DEFFCT CHAR[n] name( ): a function that returns a string.
                KrlToken size = Peek;
                if (size.Kind != KrlTokenKind.Int || Whole(size) < 1)
                {
                    throw Error(size, $"an array size must be a whole number above 0, not {size.Display}");
                }
                _at++;
                Expect("]");
                returns = KrlType.Array(KrlType.Char, Whole(size));
            }
        }
        else if (def.Is("DEF"))
        {
            _at++;
        }
        else
        {
            throw Error(def, $"expected DEF or DEFFCT, found {def.Display}");
        }
        string name = Identifier("the routine's name");
        var routine = new KrlRoutine(_file, name, def.Line) { Module = module, ReturnType = returns, IsGlobal = global || first };
        Expect("(");
        if (!Peek.IsSymbol(")"))
        {
            do
            {
                string parameter = Identifier("a parameter's name");
                bool array = false;
                if (Peek.IsSymbol("["))
                {
                    _at++;
                    Expect("]");
                    array = true;
                }
                bool isOut = false;
                if (Peek.IsSymbol(":"))
                {
                    _at++;
                    KrlToken how = Peek;
                    if (how.Is("OUT"))
                    {
                        isOut = true;
                    }
                    else if (!how.Is("IN"))
                    {
                        throw Error(how, $"a parameter is :IN or :OUT, not {how.Display}");
                    }
                    _at++;
                }
                if (routine.Parameters.Any(p => string.Equals(p.Name, parameter, StringComparison.OrdinalIgnoreCase)))
                {
                    throw Error(def, $"the parameter {parameter} is named twice");
                }
                routine.Parameters.Add(new KrlParameter(parameter, isOut, array));
            }
            while (Accept(","));
        }
        Expect(")");
        EndOfLine();
        string end = returns is null ? "END" : "ENDFCT";
        bool declarations = true;
        var declared = new List<(string Name, KrlType Type, int Line)>();
        while (!Peek.Is(end))
        {
            if (Peek.Kind == KrlTokenKind.End || Peek.Is("DEF") || Peek.Is("DEFFCT"))
            {
                throw Error(Peek, $"{end} is missing for {name} (line {def.Line})");
            }
            if (IsDeclaration())
            {
                if (!declarations)
                {
                    throw Error(Peek, "a declaration must come before the first statement of the routine");
                }
                foreach (KrlDeclaration d in Declaration(allowInitial: false))
                {
                    declared.Add((d.Name, d.Type, d.Line));
                }
                continue;
            }
            declarations = false;
            routine.Body.Add(Statement());
        }
        _at++;
        EndOfLine();
        foreach (KrlParameter parameter in routine.Parameters)
        {
            (string Name, KrlType Type, int Line) d = declared.FirstOrDefault(l => string.Equals(l.Name, parameter.Name, StringComparison.OrdinalIgnoreCase));
            if (d.Name is null)
            {
                throw new KrlLoadException(_file, def.Line, $"the parameter {parameter.Name} of {name} has no DECL in the routine");
            }
            parameter.Type = d.Type;
            routine.Locals.Add(d);
        }
        foreach ((string Name, KrlType Type, int Line) d in declared)
        {
            if (routine.Parameters.Any(p => string.Equals(p.Name, d.Name, StringComparison.OrdinalIgnoreCase)))
            {
                continue;
            }
            if (routine.SlotOf(d.Name) >= 0)
            {
                throw new KrlLoadException(_file, d.Line, $"{d.Name} is declared twice in {name}");
            }
            routine.Locals.Add(d);
        }
        return routine;
    }

    /// <summary>True when the line starts a declaration: DECL, EXT, EXTFCT, or a type name followed by a variable name.</summary>
    private bool IsDeclaration() => Peek.Is("DECL") || Peek.Is("STRUC") || Peek.Is("ENUM") || IsExternal()
        || (Peek.Kind == KrlTokenKind.Name && KrlUserTypes.Find(_userTypes, Peek.Text) is not null && PeekAt(1).Kind == KrlTokenKind.Name);

    /// <summary>[DECL] [GLOBAL] [CONST] type name[sizes] [= value], name…</summary>
    private List<KrlDeclaration> Declaration(bool allowInitial)
    {
        if (IsExternal())
        {
            External();
            return [];
        }
        Accept("DECL");
        bool global = Accept("GLOBAL");
        if (Peek.Is("STRUC") || Peek.Is("ENUM"))
        {
            // Read with the other files' types before the files were parsed (KrlUserTypes).
            while (Peek.Kind is not (KrlTokenKind.EndOfLine or KrlTokenKind.End))
            {
                _at++;
            }
            EndOfLine();
            return [];
        }
        Accept("CONST");
        KrlType element = TypeName();
        var result = new List<KrlDeclaration>();
        do
        {
            KrlToken nameToken = Peek;
            string name = Identifier("a variable's name");
            KrlType type = element;
            if (Peek.IsSymbol("["))
            {
                _at++;
                var sizes = new List<int>();
                if (Peek.IsSymbol("]"))
                {
                    sizes.Add(0);
                }
                else
                {
                    do
                    {
                        KrlToken size = Peek;
                        if (size.Kind != KrlTokenKind.Int || Whole(size) < 1)
                        {
                            throw Error(size, $"an array size must be a whole number above 0, not {size.Display}");
                        }
                        sizes.Add(Whole(size));
                        _at++;
                    }
                    while (Accept(","));
                }
                Expect("]");
                if (sizes.Count > 3)
                {
                    throw Error(nameToken, "KRL arrays have at most 3 dimensions");
                }
                long count = _limits.Elements(sizes) ?? throw Error(nameToken, $"{nameToken.Text}: {_limits.ArrayTooLarge(sizes)}");
                if ((_elements += count) > _limits.MaxTotalElements)
                {
                    throw Error(nameToken, $"the file's data hold more than {_limits.MaxTotalElements:N0} array elements (the twin's limit)");
                }
                type = KrlType.Array(element, [.. sizes]);
            }
            KrlExpr? initial = null;
            if (Peek.IsSymbol("="))
            {
                if (!allowInitial)
                {
                    throw Error(Peek, "a variable declared in a routine cannot be initialised in its DECL; assign it in a statement");
                }
                _at++;
                initial = Expression();
            }
            result.Add(new KrlDeclaration(name, type, initial, global, nameToken.Line));
        }
        while (Accept(","));
        EndOfLine();
        return result;
    }

    private KrlType TypeName()
    {
        KrlToken token = Peek;
        KrlType? type = token.Kind == KrlTokenKind.Name ? KrlUserTypes.Find(_userTypes, token.Text) : null;
        if (type is null)
        {
            throw Error(token, (token.Kind == KrlTokenKind.Name ? KrlUnsupported.Type(token.Text) : null) ?? $"unknown data type {token.Display}");
        }
        _at++;
        return type;
    }

    /// <summary>A structure component's name after '.' or in an aggregate: any name, also a word KRL reserves elsewhere (STEP, TYPE).</summary>
    private string Component()
    {
        KrlToken token = Peek;
        if (token.Kind != KrlTokenKind.Name || token.Text.StartsWith('$'))
        {
            throw Error(token, $"expected a structure component, found {token.Display}");
        }
        _at++;
        return token.Text;
    }

    private string Identifier(string what)
    {
        KrlToken token = Peek;
        if (token.Kind != KrlTokenKind.Name || KrlKeywords.IsReserved(token.Text))
        {
            throw Error(token, $"expected {what}, found {token.Display}");
        }
        _at++;
        return token.Text;
    }

    private KrlToken Expect(string symbolOrWord)
    {
        KrlToken token = Peek;
        if (!(token.IsSymbol(symbolOrWord) || token.Is(symbolOrWord)))
        {
            throw Error(token, $"expected '{symbolOrWord}', found {token.Display}");
        }
        _at++;
        return token;
    }

    private bool Accept(string symbolOrWord)
    {
        if (Peek.IsSymbol(symbolOrWord) || Peek.Is(symbolOrWord))
        {
            _at++;
            return true;
        }
        return false;
    }

    private void EndOfLine()
    {
        KrlToken token = Peek;
        if (token.Kind == KrlTokenKind.End)
        {
            return;
        }
        if (token.Kind != KrlTokenKind.EndOfLine)
        {
            throw Error(token, token.Is("MOD")
                ? "KRL has no operator MOD: its arithmetic operators are + - * / (INT division with / truncates)"
                : $"unexpected {token.Display}: the statement should end here");
        }
        _cancellation.ThrowIfCancellationRequested();
        _at++;
    }

    private void SkipLines()
    {
        while (Peek.Kind == KrlTokenKind.EndOfLine)
        {
            _at++;
        }
    }

    private KrlLoadException Error(KrlToken at, string reason) => new(_file, at.Line, reason);
}

/// <summary>A variable declaration: name, type, initial value (data lists only), GLOBAL, line.</summary>
internal sealed record KrlDeclaration(string Name, KrlType Type, KrlExpr? Initial, bool Global, int Line);

/// <summary>A DEFDAT data list as read from its file.</summary>
internal sealed class KrlDataList(string file, string name, bool isPublic, int line)
{
    /// <summary>The file.</summary>
    public string File { get; } = file;

    /// <summary>The data list's (module's) name.</summary>
    public string Name { get; } = name;

    /// <summary>True for DEFDAT … PUBLIC: its GLOBAL variables are visible to every module.</summary>
    public bool IsPublic { get; } = isPublic;

    /// <summary>The line of DEFDAT.</summary>
    public int Line { get; } = line;

    /// <summary>The declarations, in order.</summary>
    public List<KrlDeclaration> Declarations { get; } = [];

    /// <summary>The routines its EXT and EXTFCT declarations name.</summary>
    public List<KrlExternal> Externals { get; } = [];

    /// <summary>The array elements given a value after their array's DECL, in order.</summary>
    public List<KrlElementInitialiser> Elements { get; } = [];
}
