using Machina.Simulation.Twin;

namespace Machina.Simulation.UrScript;

/// <summary>A program ready to run: every name resolved to a slot, every call to a built-in or a function of the program.</summary>
internal sealed class UrBoundProgram(List<UrStmt> statements, UrFunction? entry, string[] globals, Dictionary<string, UrFunction> functions)
{
    /// <summary>The statements outside any definition, run in order (empty when the program is a lone def).</summary>
    public List<UrStmt> Statements { get; } = statements;

    /// <summary>The def that is run when there are no statements outside definitions: the last top-level def.</summary>
    public UrFunction? Entry { get; } = entry;

    /// <summary>The names of the global slots.</summary>
    public string[] Globals { get; } = globals;

    /// <summary>Every function and thread by name.</summary>
    public Dictionary<string, UrFunction> Functions { get; } = functions;

    /// <summary>True when the program is a secondary program (its entry is a <c>sec</c>).</summary>
    public bool IsSecondary => Entry?.IsSecondary == true;

    /// <summary>The first call of a built-in that uses physical time (motion, <c>sleep</c>, <c>sync</c>), or null when there is none.</summary>
    public (string Name, int Line)? PhysicalTimeCall { get; init; }
}

/// <summary>
/// Resolves a parsed program as the controller's compiler does before anything runs: unknown functions, unknown named
/// arguments, wrong argument counts and variables that are never assigned are compile errors with their line.
/// Scopes follow the Script Manual: the variables of the program (a top-level def without parameters) and of the text outside
/// definitions are global, and so is one declared <c>global</c> anywhere; in another function a variable that is assigned
/// without a qualifier (a free variable) is the global of that name when there is one, else local; <c>local</c> makes it local.
/// </summary>
internal sealed class UrBinder
{
    private readonly IReadOnlyDictionary<string, UrBuiltin> _builtins;
    private readonly Dictionary<string, UrFunction> _functions = new(StringComparer.Ordinal);
    private readonly Dictionary<string, int> _globals = new(StringComparer.Ordinal);
    private readonly Dictionary<object, UrConst> _defaults = new(ReferenceEqualityComparer.Instance);
    private Dictionary<string, int>? _locals;
    private (string Name, int Line)? _physicalTimeCall;

    /// <summary>The built-ins that use physical (robot) time: a secondary program cannot call them (the Script Manual's "Secondary Programs").</summary>
    private static readonly HashSet<string> PhysicalTime = new(StringComparer.Ordinal)
    {
        "movej", "movel", "movep", "movec", "servoj", "speedj", "speedl", "stopj", "stopl", "sleep", "sync",
    };

    private UrBinder(IReadOnlyDictionary<string, UrBuiltin> builtins) => _builtins = builtins;

    /// <summary>Binds <paramref name="tree"/> against the built-ins.</summary>
    /// <exception cref="UrCompileException">The first error, with its line.</exception>
    public static UrBoundProgram Bind(UrSyntaxTree tree, IReadOnlyDictionary<string, UrBuiltin> builtins)
    {
        var binder = new UrBinder(builtins);
        foreach (UrFunction function in tree.Functions)
        {
            if (builtins.ContainsKey(function.Name))
            {
                throw new UrCompileException(function.Line, $"'{function.Name}' is a built-in function and cannot be defined again");
            }
            if (!binder._functions.TryAdd(function.Name, function))
            {
                throw new UrCompileException(function.Line, $"'{function.Name}' is defined twice");
            }
        }
        CollectAssigned(tree.Statements, binder._globals, null);
        foreach (UrFunction function in tree.Functions)
        {
            CollectGlobalDeclarations(function.Body, binder._globals);
            if (function.IsProgram)
            {
                CollectAssigned(function.Body, binder._globals, null);
            }
        }
        binder.BindBlock(tree.Statements);
        foreach (UrFunction function in tree.Functions)
        {
            binder.BindFunction(function);
        }
        UrFunction? entry = tree.TopLevel.LastOrDefault(f => f.IsProgram);
        return new UrBoundProgram(tree.Statements, entry, [.. binder._globals.OrderBy(g => g.Value).Select(g => g.Key)], binder._functions)
        {
            PhysicalTimeCall = binder._physicalTimeCall,
        };
    }

    private void BindFunction(UrFunction function)
    {
        var declaredGlobal = new HashSet<string>(StringComparer.Ordinal);
        var declaredLocal = new HashSet<string>(StringComparer.Ordinal);
        CollectDeclarations(function.Body, declaredGlobal, declaredLocal);
        var locals = new Dictionary<string, int>(StringComparer.Ordinal);
        foreach (string parameter in function.Parameters)
        {
            if (!locals.TryAdd(parameter, locals.Count))
            {
                throw new UrCompileException(function.Line, $"parameter '{parameter}' is named twice");
            }
        }
        foreach (string name in declaredLocal)
        {
            locals.TryAdd(name, locals.Count);
        }
        if (!function.IsProgram)
        {
            var assigned = new Dictionary<string, int>(StringComparer.Ordinal);
            CollectAssigned(function.Body, assigned, declaredGlobal);
            foreach (string name in assigned.Keys.Where(name => !_globals.ContainsKey(name)))
            {
                locals.TryAdd(name, locals.Count); // a free variable is the global of its name when there is one (the manual's scoping rules)
            }
        }
        foreach (UrExpr? value in function.Defaults)
        {
            if (value is not null)
            {
                BindExpr(value);
            }
        }
        _locals = locals;
        BindBlock(function.Body);
        _locals = null;
        function.LocalCount = locals.Count;
    }

    private static void CollectGlobalDeclarations(List<UrStmt> block, Dictionary<string, int> globals)
    {
        var declaredGlobal = new HashSet<string>(StringComparer.Ordinal);
        CollectDeclarations(block, declaredGlobal, new HashSet<string>(StringComparer.Ordinal));
        foreach (string name in declaredGlobal)
        {
            globals.TryAdd(name, globals.Count);
        }
    }

    private static void CollectDeclarations(List<UrStmt> block, HashSet<string> globals, HashSet<string> locals)
    {
        foreach (UrStmt statement in block)
        {
            switch (statement)
            {
                case UrDecl d:
                    (d.IsGlobal ? globals : locals).Add(d.Name);
                    break;
                case UrIf i:
                    foreach ((_, List<UrStmt> body) in i.Branches)
                    {
                        CollectDeclarations(body, globals, locals);
                    }
                    if (i.Otherwise is not null)
                    {
                        CollectDeclarations(i.Otherwise, globals, locals);
                    }
                    break;
                case UrWhile w:
                    CollectDeclarations(w.Body, globals, locals);
                    break;
            }
        }
    }

    private static void CollectAssigned(List<UrStmt> block, Dictionary<string, int> into, HashSet<string>? except)
    {
        foreach (UrStmt statement in block)
        {
            switch (statement)
            {
                case UrAssign { Target: UrName name } when except is null || !except.Contains(name.Name):
                    into.TryAdd(name.Name, into.Count);
                    break;
                case UrDecl { Initial: not null } d when except is null || !except.Contains(d.Name):
                    into.TryAdd(d.Name, into.Count);
                    break;
                case UrIf i:
                    foreach ((_, List<UrStmt> body) in i.Branches)
                    {
                        CollectAssigned(body, into, except);
                    }
                    if (i.Otherwise is not null)
                    {
                        CollectAssigned(i.Otherwise, into, except);
                    }
                    break;
                case UrWhile w:
                    CollectAssigned(w.Body, into, except);
                    break;
            }
        }
    }

    private void BindBlock(List<UrStmt> block)
    {
        foreach (UrStmt statement in block)
        {
            switch (statement)
            {
                case UrAssign a:
                    BindExpr(a.Target);
                    BindExpr(a.Value);
                    break;
                case UrDecl { Initial: not null } d:
                    BindExpr(d.Initial.Target);
                    BindExpr(d.Initial.Value);
                    break;
                case UrExprStmt e:
                    BindExpr(e.Expr);
                    break;
                case UrIf i:
                    foreach ((UrExpr condition, List<UrStmt> body) in i.Branches)
                    {
                        BindExpr(condition);
                        BindBlock(body);
                    }
                    if (i.Otherwise is not null)
                    {
                        BindBlock(i.Otherwise);
                    }
                    break;
                case UrWhile w:
                    BindExpr(w.Condition);
                    BindBlock(w.Body);
                    break;
                case UrJump { Value: not null } j:
                    BindExpr(j.Value);
                    break;
                case UrThreadControl t:
                    BindExpr(t.Handle);
                    break;
            }
        }
    }

    private void BindExpr(UrExpr expr)
    {
        if (TwinLimits.StackLow)
        {
            throw new UrCompileException(expr.Line, "the expression is nested too deeply");
        }
        switch (expr)
        {
            case UrName name:
                if (_locals is not null && _locals.TryGetValue(name.Name, out int local))
                {
                    name.IsLocal = true;
                    name.Slot = local;
                }
                else if (_globals.TryGetValue(name.Name, out int global))
                {
                    name.Slot = global;
                }
                else
                {
                    throw new UrCompileException(name.Line, _functions.ContainsKey(name.Name) || _builtins.ContainsKey(name.Name)
                        ? $"function '{name.Name}' is used as a variable (call it with parentheses)"
                        : $"variable '{name.Name}' is not defined");
                }
                break;
            case UrIndex index:
                BindExpr(index.Target);
                BindExpr(index.Index);
                break;
            case UrUnary unary:
                BindExpr(unary.Operand);
                break;
            case UrBinary binary:
                BindExpr(binary.Left);
                BindExpr(binary.Right);
                break;
            case UrLogical logical:
                BindExpr(logical.Left);
                BindExpr(logical.Right);
                break;
            case UrListExpr list:
                list.Items.ToList().ForEach(BindExpr);
                break;
            case UrPoseExpr pose:
                pose.Items.ToList().ForEach(BindExpr);
                break;
            case UrRunExpr run:
                run.Thread = _functions.TryGetValue(run.Name, out UrFunction? thread) && thread.IsThread
                    ? thread
                    : throw new UrCompileException(run.Line, $"'{run.Name}' is not a thread of this program");
                break;
            case UrCall call:
                BindCall(call);
                break;
        }
    }

    private void BindCall(UrCall call)
    {
        (string Name, object? Default)[] parameters;
        if (_builtins.TryGetValue(call.Name, out UrBuiltin? builtin))
        {
            call.Builtin = builtin;
            parameters = builtin.Parameters;
            if (_physicalTimeCall is null && PhysicalTime.Contains(call.Name))
            {
                _physicalTimeCall = (call.Name, call.Line);
            }
        }
        else if (_functions.TryGetValue(call.Name, out UrFunction? function) && !function.IsThread)
        {
            call.Function = function;
            parameters = function.Parameters.Select((p, i) => (p, (object?)function.Defaults[i])).ToArray();
        }
        else
        {
            throw new UrCompileException(call.Line, _functions.ContainsKey(call.Name)
                ? $"thread '{call.Name}' must be started with run"
                : $"unknown function '{call.Name}'");
        }
        if (call.Positional.Count > parameters.Length)
        {
            throw new UrCompileException(call.Line, $"{call.Name} takes at most {parameters.Length} arguments, {call.Positional.Count} given");
        }
        var arguments = new UrExpr?[parameters.Length];
        for (int i = 0; i < call.Positional.Count; i++)
        {
            arguments[i] = call.Positional[i];
        }
        foreach ((string key, UrExpr value) in call.Named)
        {
            int at = IndexOf(parameters, key);
            if (at < 0)
            {
                throw new UrCompileException(call.Line, $"{call.Name} has no parameter '{key}'");
            }
            if (arguments[at] is not null)
            {
                throw new UrCompileException(call.Line, $"{call.Name} got parameter '{key}' twice");
            }
            arguments[at] = value;
        }
        for (int i = 0; i < parameters.Length; i++)
        {
            if (arguments[i] is null)
            {
                arguments[i] = parameters[i].Default switch
                {
                    null => throw new UrCompileException(call.Line, $"{call.Name} is missing its argument '{parameters[i].Name}'"),
                    UrExpr e => e,
                    object constant => DefaultNode(call.Line, constant),
                };
            }
            BindExpr(arguments[i]!);
            arguments[i] = UrConstPose.Fold(arguments[i]!);
        }
        call.Arguments = arguments!;
    }

    /// <summary>The node of a built-in's default value, made once for all calls (a constant never fails, so its line is not read).</summary>
    private UrConst DefaultNode(int line, object constant)
    {
        if (!_defaults.TryGetValue(constant, out UrConst? node))
        {
            node = new UrConst(line, constant);
            _defaults[constant] = node;
        }
        return node;
    }

    private static int IndexOf((string Name, object? Default)[] parameters, string name)
    {
        for (int i = 0; i < parameters.Length; i++)
        {
            if (parameters[i].Name == name)
            {
                return i;
            }
        }
        return -1;
    }
}
