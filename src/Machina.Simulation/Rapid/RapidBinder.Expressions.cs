using Machina.Simulation.Twin;

namespace Machina.Simulation.Rapid;

/// <summary>Expressions, data references and calls.</summary>
internal sealed partial class RapidBinder
{
    private static readonly RapidDataType NumType = new(RapidTypes.Num);
    private static readonly RapidDataType BoolType = new(RapidTypes.Bool);
    private static readonly RapidDataType StringType = new(RapidTypes.String);

    /// <summary>Binds <paramref name="e"/> and checks that its type fits <paramref name="expected"/> (null: any).</summary>
    private RapidDataType? BindValue(RapidExpr e, RapidDataType? expected, RapidScope scope)
    {
        RapidDataType? type = AsValue(e, BindExpression(e, expected, scope), expected);
        if (expected is { } want && type is { } got && !want.Accepts(got))
        {
            throw Refuse(e.Line, RapidLoadException.Type($"type mismatch: expected {want}, found {got}"));
        }
        return type;
    }

    /// <summary>Binds data that is written: it must be a variable, persistent or reference parameter, not a constant.</summary>
    private RapidDataType? BindTarget(RapidExpr e, RapidScope scope, string verb)
    {
        if (e.Root is not RapidName name)
        {
            throw Refuse(e.Line, RapidLoadException.Reference("only data can be " + verb));
        }
        RapidDataType? type = BindExpression(e, null, scope);
        if (scope.Find(name.Name) is { ReadOnly: true })
        {
            throw Refuse(e.Line, RapidLoadException.Reference($"'{name.Name}' is read-only and cannot be {verb}"));
        }
        if (name.Global is { Storage: RapidStorage.Const })
        {
            throw Refuse(e.Line, RapidLoadException.Reference($"'{name.Name}' is a constant and cannot be {verb}"));
        }
        NoteWrite(name, scope);
        return type;
    }

    /// <summary>Notes that the routine being bound may write the data <paramref name="name"/> (bound already) when it is one of its parameters.</summary>
    private static void NoteWrite(RapidName name, RapidScope scope)
    {
        if (name.Global is null && scope.Routine is { } routine && name.Slot >= 0 && name.Slot < routine.Parameters.Count)
        {
            routine.WritesParameter[name.Slot] = true;
        }
    }

    /// <summary>True when <paramref name="e"/> calls a function somewhere (which might write data through a reference parameter).</summary>
    private static bool CallsAFunction(RapidExpr e) => e switch
    {
        RapidCallExpr => true,
        RapidComponent c => CallsAFunction(c.Target),
        RapidIndex i => CallsAFunction(i.Target) || i.Indices.Any(CallsAFunction),
        RapidAggregate a => a.Items.Any(CallsAFunction),
        RapidUnary u => CallsAFunction(u.Operand),
        RapidBinary b => CallsAFunction(b.Left) || CallsAFunction(b.Right),
        _ => false,
    };

    private RapidDataType? BindExpression(RapidExpr e, RapidDataType? expected, RapidScope scope)
    {
        if (TwinLimits.StackLow)
        {
            throw Refuse(e.Line, RapidLoadException.Syntax("the expression is nested too deeply"));
        }
        RapidDataType? type = e switch
        {
            RapidLiteral { Value: double } => NumType,
            RapidLiteral { Value: string } => StringType,
            RapidLiteral => BoolType,
            RapidName n => BindName(n, scope),
            RapidComponent c => BindComponent(c, scope),
            RapidIndex i => BindIndex(i, scope),
            RapidAggregate a => BindAggregate(a, expected, scope),
            RapidUnary u => BindUnary(u, scope),
            RapidBinary b => BindBinary(b, scope),
            RapidCallExpr call => BindFunction(call, scope),
            _ => throw Refuse(e.Line, RapidLoadException.Syntax("unknown expression")),
        };
        e.Type = type;
        if (e is RapidBinary binary)
        {
            binary.NumberOperands = IsNumber(binary.Left.Type) && IsNumber(binary.Right.Type);
        }
        return type;
    }

    /// <summary>True for a numeric type (num or dnum) that is not an array.</summary>
    private static bool IsNumber(RapidDataType? type) => type is { Rank: 0 } t && t.Element.IsNumeric;

    private RapidDataType BindName(RapidName n, RapidScope scope)
    {
        if (scope.Find(n.Name) is { } local)
        {
            n.Slot = local.Slot;
            return scope.Routine!.SlotTypes[local.Slot];
        }
        if (GlobalData(n.Name) is { } cell)
        {
            n.Global = cell;
            return cell.Type;
        }
        if (n.Name.Equals("ERRNO", StringComparison.OrdinalIgnoreCase))
        {
            n.Global = _program.Errno;
            return _program.Errno.Type;
        }
        if (IsDataToCome(n.Name))
        {
            throw new WaitsForData();
        }
        string what = RoutineNamed(n.Name) is not null || _builtins.ContainsKey(n.Name) ? "is a routine, not data" : "is unknown (not data)";
        throw Refuse(n.Line, RapidLoadException.Reference($"'{n.Name}' {what}"));
    }

    private RapidDataType? BindComponent(RapidComponent c, RapidScope scope)
    {
        RapidDataType? target = BindExpression(c.Target, null, scope);
        if (target is not { Rank: 0, Element.Kind: RapidTypeKind.Record } record)
        {
            throw Refuse(c.Line, RapidLoadException.Type($"'{c.Name}': {target?.ToString() ?? "this value"} is not a record"));
        }
        c.Index = record.Element.IndexOf(c.Name);
        return c.Index >= 0 ? record.Element.Fields[c.Index].Type
            : throw Refuse(c.Line, RapidLoadException.Reference($"'{c.Name}' is not a component of {record.Element.Name}"));
    }

    private RapidDataType? BindIndex(RapidIndex i, RapidScope scope)
    {
        RapidDataType? target = BindExpression(i.Target, null, scope);
        if (target is not { } array || array.Rank != i.Indices.Length)
        {
            throw Refuse(i.Line, RapidLoadException.Type($"{target?.ToString() ?? "this value"} cannot take {i.Indices.Length} index(es)"));
        }
        foreach (RapidExpr index in i.Indices)
        {
            BindValue(index, NumType, scope);
        }
        return new RapidDataType(array.Element);
    }

    private RapidDataType BindAggregate(RapidAggregate a, RapidDataType? expected, RapidScope scope)
    {
        if (expected is not { } want)
        {
            throw Refuse(a.Line, RapidLoadException.Type("an aggregate [ … ] is not allowed here (its type is unknown)"));
        }
        if (want.Rank > 0)
        {
            var element = new RapidDataType(want.Element, want.Rank - 1);
            foreach (RapidExpr item in a.Items)
            {
                BindValue(item, element, scope);
            }
            return want;
        }
        if (want.Element.Kind != RapidTypeKind.Record)
        {
            throw Refuse(a.Line, RapidLoadException.Type($"an aggregate [ … ] cannot be a {want}"));
        }
        IReadOnlyList<(string Name, RapidDataType Type)> fields = want.Element.Fields;
        if (a.Items.Length != fields.Count)
        {
            throw Refuse(a.Line, RapidLoadException.Type($"a {want.Element.Name} has {fields.Count} components, the aggregate has {a.Items.Length}"));
        }
        for (int k = 0; k < fields.Count; k++)
        {
            BindValue(a.Items[k], fields[k].Type, scope);
        }
        return want;
    }

    private RapidDataType BindUnary(RapidUnary u, RapidScope scope)
    {
        if (u.Op == "NOT")
        {
            BindValue(u.Operand, BoolType, scope);
            return BoolType;
        }
        RapidDataType? type = BindExpression(u.Operand, null, scope);
        return type is { Rank: 0 } t && (t.Element.IsNumeric || t.Element == RapidTypes.Pos) ? t
            : throw Refuse(u.Line, RapidLoadException.Type($"'{u.Op}' needs a num, not a {type}"));
    }

    /// <summary>
    /// A signal named where a number is expected (<c>di1 = 1</c>, <c>reg1 := gi1</c>) is read as its value, as RAPID does: the name is
    /// marked and its type becomes num. Any other expression keeps <paramref name="type"/>.
    /// </summary>
    private static RapidDataType? AsValue(RapidExpr e, RapidDataType? type, RapidDataType? expected)
    {
        if (e is RapidName name && type is { Rank: 0 } t && RapidTypes.IsSignal(t.Element) && expected is { Rank: 0 } want && want.Element.IsNumeric)
        {
            name.ReadsSignal = true;
            return NumType;
        }
        return type;
    }

    private RapidDataType BindBinary(RapidBinary b, RapidScope scope)
    {
        switch (b.Op)
        {
            case "AND" or "OR" or "XOR":
                BindValue(b.Left, BoolType, scope);
                BindValue(b.Right, BoolType, scope);
                return BoolType;
            case "=" or "<>":
            {
                RapidDataType? left = AsValue(b.Left, BindExpression(b.Left, null, scope), NumType);
                BindValue(b.Right, left, scope);
                return BoolType;
            }
            case "<" or ">" or "<=" or ">=" or "DIV" or "MOD":
                BindValue(b.Left, NumType, scope);
                BindValue(b.Right, NumType, scope);
                return b.Op is "DIV" or "MOD" ? NumType : BoolType;
        }
        RapidDataType? l = AsValue(b.Left, BindExpression(b.Left, null, scope), NumType);
        RapidDataType? r = AsValue(b.Right, BindExpression(b.Right, l is { Element.Kind: RapidTypeKind.Record } ? l : null, scope), NumType);
        if (l is { Rank: 0 } lt && r is { Rank: 0 } rt)
        {
            if (lt.Element.IsNumeric && rt.Element.IsNumeric)
            {
                return lt.Element == RapidTypes.Dnum || rt.Element == RapidTypes.Dnum ? new RapidDataType(RapidTypes.Dnum) : NumType;
            }
            if (b.Op == "+" && lt.Element.Kind == RapidTypeKind.String && rt.Element.Kind == RapidTypeKind.String)
            {
                b.Concatenation = [.. PartsOf(b.Left), .. PartsOf(b.Right)];
                return StringType;
            }
            if (b.Op is "+" or "-" && lt.Element == RapidTypes.Pos && rt.Element == RapidTypes.Pos)
            {
                return lt;
            }
            if (b.Op is "*" && (lt.Element == RapidTypes.Pos && rt.Element.IsNumeric || lt.Element.IsNumeric && rt.Element == RapidTypes.Pos))
            {
                return new RapidDataType(RapidTypes.Pos);
            }
        }
        throw Refuse(b.Line, RapidLoadException.Type($"'{b.Op}' cannot combine {l?.ToString() ?? "this value"} and {r?.ToString() ?? "this value"}"));
    }

    /// <summary>The operands of a string concatenation in their order: those of a concatenation inside it, else the expression itself.</summary>
    private static RapidExpr[] PartsOf(RapidExpr e) => e is RapidBinary { Concatenation: { } parts } ? parts : [e];

    private RapidDataType? BindFunction(RapidCallExpr call, RapidScope scope)
    {
        call.Target = BindCall(call.Name, call.Args, call.Line, scope, procedure: false);
        if (call.Target.Routine is { } routine)
        {
            return routine.ReturnType;
        }
        return call.Target.Builtin!.Returns is { } returns ? new RapidDataType(TypeNamed(returns, call.Line)) : null;
    }

    /// <summary>Finds the routine a call names and matches its arguments to the parameters, checking their types.</summary>
    private RapidCallTarget BindCall(string name, RapidArg[] args, int line, RapidScope scope, bool procedure)
    {
        RapidRoutine? routine = RoutineNamed(name);
        RapidBuiltin? builtin = routine is null ? _builtins.GetValueOrDefault(name) : null;
        bool isFunction = routine?.Kind == RapidRoutineKind.Func || builtin?.Returns is not null;
        if ((routine is null && builtin is null) || routine?.Kind == RapidRoutineKind.Trap)
        {
            string what = GlobalData(name) is not null ? "is data, not a routine" : procedure ? "is not a procedure (unknown instruction)" : "is not a function";
            throw Refuse(line, RapidLoadException.Reference($"'{name}' {what}"));
        }
        if (procedure == isFunction)
        {
            throw Refuse(line, RapidLoadException.Reference(procedure ? $"'{name}' is a function, not a procedure" : $"'{name}' is a procedure, not a function"));
        }
        List<(string Name, string? Type, bool Optional, bool Switch, bool Ref, int Rank)> ps = Signature(routine, builtin!);
        int[] map = new int[ps.Count];
        Array.Fill(map, -1);
        int next = 0;
        for (int k = 0; k < args.Length; k++)
        {
            RapidArg arg = args[k];
            int p;
            if (arg.Name is null)
            {
                while (next < ps.Count && ps[next].Optional)
                {
                    next++;
                }
                if (next >= ps.Count)
                {
                    throw Refuse(arg.Line, RapidLoadException.Reference($"too many arguments for '{name}'"));
                }
                p = next++;
            }
            else
            {
                p = ps.FindIndex(x => x.Optional && x.Name.Equals(arg.Name, StringComparison.OrdinalIgnoreCase));
                if (p < 0)
                {
                    throw Refuse(arg.Line, RapidLoadException.Reference($"'{name}' has no optional argument '\\{arg.Name}'"));
                }
                if (map[p] >= 0)
                {
                    throw Refuse(arg.Line, RapidLoadException.Reference($"'\\{arg.Name}' is given twice"));
                }
            }
            map[p] = k;
            BindArgument(name, arg, ps[p], line, scope);
        }
        for (int missing = 0; missing < ps.Count; missing++)
        {
            if (!ps[missing].Optional && map[missing] < 0)
            {
                throw Refuse(line, RapidLoadException.Reference($"the argument '{ps[missing].Name}' of '{name}' is missing"));
            }
        }
        return new RapidCallTarget(builtin, routine, map) { ArgumentsCallNoFunction = !args.Any(a => a.Value is not null && CallsAFunction(a.Value)) };
    }

    private readonly Dictionary<object, List<(string Name, string? Type, bool Optional, bool Switch, bool Ref, int Rank)>> _signatures = [];

    /// <summary>The parameters of a routine or built-in in one shape, made once per routine.</summary>
    private List<(string Name, string? Type, bool Optional, bool Switch, bool Ref, int Rank)> Signature(RapidRoutine? routine, RapidBuiltin builtin)
    {
        object key = (object?)routine ?? builtin;
        if (!_signatures.TryGetValue(key, out List<(string, string?, bool, bool, bool, int)>? ps))
        {
            ps = routine is not null
                ? [.. routine.Parameters.Select(p => (p.Name, (string?)p.TypeName, p.Optional, p.IsSwitch, p.Mode != RapidParamMode.In, p.Rank))]
                : [.. builtin.Parameters.Select(p => (p.Name, p.Type, p.Optional, p.Switch, p.Ref, p.Rank))];
            _signatures[key] = ps;
        }
        return ps;
    }

    private void BindArgument(string routine, RapidArg arg, (string Name, string? Type, bool Optional, bool Switch, bool Ref, int Rank) p, int line, RapidScope scope)
    {
        if (p.Switch)
        {
            if (arg.Value is not null)
            {
                throw Refuse(arg.Line, RapidLoadException.Type($"'\\{p.Name}' of '{routine}' is a switch and takes no value"));
            }
            return;
        }
        if (arg.Value is null)
        {
            throw Refuse(arg.Line, RapidLoadException.Type($"the argument '{p.Name}' of '{routine}' needs a value"));
        }
        RapidDataType? expected = p.Type is null ? null : new RapidDataType(TypeNamed(p.Type, line), p.Rank);
        if (p.Ref)
        {
            RapidDataType? type = BindTarget(arg.Value, scope, $"passed as '{p.Name}' of '{routine}'");
            if (expected is { } want && type is { } got && !(want.Rank == got.Rank && (want.Element.Canonical.Equals(got.Element.Canonical, StringComparison.OrdinalIgnoreCase)
                || (RapidTypes.IsSignal(want.Element) && RapidTypes.IsSignal(got.Element)) || (want.Element.IsNumeric && got.Element.IsNumeric))))
            {
                throw Refuse(arg.Value.Line, RapidLoadException.Type($"type mismatch: '{p.Name}' of '{routine}' is a {want}, found {got}"));
            }
            return;
        }
        if (expected is { } signal && RapidTypes.IsSignal(signal.Element))
        {
            RapidDataType? got = BindExpression(arg.Value, null, scope);
            if (got is not { } g || !RapidTypes.IsSignal(g.Element))
            {
                throw Refuse(arg.Value.Line, RapidLoadException.Type($"type mismatch: '{p.Name}' of '{routine}' is a signal, found {got}"));
            }
            return;
        }
        BindValue(arg.Value, expected, scope);
    }
}
