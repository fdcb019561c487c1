using Machina.Simulation.Twin;

namespace Machina.Simulation.Krl;

/// <summary>Names, calls and the types of expressions.</summary>
internal sealed partial class KrlBinder
{
    /// <summary>The type of <paramref name="expr"/> (an aggregate without a type name takes <paramref name="expected"/>).</summary>
    private KrlType Expr(KrlExpr expr, KrlType? expected)
    {
        if (TwinLimits.StackLow)
        {
            throw Error(expr.Line, "the expression is nested too deeply");
        }
        expr.Type = expr switch
        {
            KrlLiteral literal => literal.Value switch
            {
                int => KrlType.Int,
                double => KrlType.Real,
                bool => KrlType.Bool,
                KrlEnumValue => KrlType.Enum,
                string s => Text(literal, s),
                _ => throw Error(expr.Line, "an unknown constant"),
            },
            KrlName name => Name(name),
            KrlIndex index => Index(index),
            KrlMember member => Member(member),
            KrlCall call => Call(call, statement: false) ?? KrlType.Int,
            KrlUnary unary => Unary(unary),
            KrlBinary binary => Binary(binary),
            KrlAggregate aggregate => Aggregate(aggregate, expected),
            _ => throw Error(expr.Line, "an unknown expression"),
        };
        return expr.Type;
    }

    /// <summary>
    /// The type of string literal <paramref name="literal"/>, whose value becomes the program's one string of its text: a channel
    /// name or tag written at each EKI_ call is then the same string at each, found by reference (a case-insensitive compare of
    /// its characters before, at every call).
    /// </summary>
    private KrlType Text(KrlLiteral literal, string text)
    {
        if (_texts.TryGetValue(text, out string? kept))
        {
            literal.Value = kept;
        }
        else
        {
            _texts.Add(text, text);
        }
        return KrlType.Array(KrlType.Char, Math.Max(1, text.Length));
    }

    private KrlType Name(KrlName name)
    {
        int slot = _routine?.SlotOf(name.Name) ?? -1;
        if (slot >= 0)
        {
            name.Slot = slot;
            return _routine!.Locals[slot].Type;
        }
        if ((_module is not null && _module.Data.TryGetValue(name.Name, out KrlCell? cell)) || TryGlobal(name.Name, out cell)
            || environment.System.TryGetValue(name.Name, out cell) || environment.Signals.TryGetValue(name.Name, out cell))
        {
            name.Cell = cell;
            return cell.Type;
        }
        if (name.Name.StartsWith('$'))
        {
            throw Error(name.Line, $"unknown system variable {name.Name} (the twin has {string.Join(", ", environment.System.Keys.Order(StringComparer.Ordinal))})");
        }
        throw Error(name.Line, FindRoutine(modules, _module, name.Name) is not null || environment.Builtins.ContainsKey(name.Name)
            ? $"{name.Name} is a routine: call it with ( )"
            : $"unknown name {name.Name}: it is not declared (DECL) in the routine, its data list or a PUBLIC data list");
    }

    private bool TryGlobal(string name, out KrlCell cell)
    {
        foreach (KrlModule other in modules.Values)
        {
            if (other.GlobalData.Contains(name))
            {
                cell = other.Data[name];
                return true;
            }
        }
        cell = null!;
        return false;
    }

    private KrlType Index(KrlIndex index)
    {
        KrlType array = Expr(index.Target, null);
        if (array.Kind != KrlKind.Array)
        {
            throw Error(index.Line, $"{Describe(index.Target)} is a {array}, not an array");
        }
        index.Access = index.Indices.Count == 0 ? KrlAccess.Whole
            : index.Indices[^1] is null || index.Target is not KrlName name ? KrlAccess.Place
            : name.Cell?.Signals is not null ? KrlAccess.Signal
            : KrlAccess.Element;
        if (index.Indices.Count == 0)
        {
            return array;
        }
        if (index.Indices.Count != array.Sizes.Count)
        {
            throw Error(index.Line, $"{Describe(index.Target)} has {array.Sizes.Count} dimension(s); {index.Indices.Count} index(es) given");
        }
        foreach (KrlExpr? i in index.Indices)
        {
            if (i is not null && Expr(i, null).Kind != KrlKind.Int)
            {
                throw Error(index.Line, $"an array index must be an INT, not {i.Type}");
            }
        }
        if (index.Indices[^1] is null)
        {
            if (array.Element!.Kind != KrlKind.Char || index.Indices.Take(index.Indices.Count - 1).Any(i => i is null))
            {
                throw Error(index.Line, "only the last index of a CHAR array may be left out (a row of characters)");
            }
            return KrlType.Array(KrlType.Char, array.Sizes[^1]);
        }
        if (index.Indices.Any(i => i is null))
        {
            throw Error(index.Line, "only the last index of a CHAR array may be left out");
        }
        return array.Element!;
    }

    private KrlType Member(KrlMember member)
    {
        KrlType structure = Expr(member.Target, null);
        int field = structure.Kind == KrlKind.Struct ? structure.FieldIndex(member.Field) : -1;
        if (field < 0)
        {
            throw Error(member.Line, structure.Kind == KrlKind.Struct
                ? $"{structure} has no component {member.Field}"
                : $"{Describe(member.Target)} is a {structure}, not a structure");
        }
        member.FieldIndex = field;
        return structure.Fields[field].Type;
    }

    private KrlType Unary(KrlUnary unary)
    {
        KrlType operand = Expr(unary.Operand, null);
        return unary.Op switch
        {
            "NOT" when operand.Kind == KrlKind.Bool => KrlType.Bool,
            "B_NOT" when operand.Kind == KrlKind.Int => KrlType.Int,
            "-" when operand.IsNumber => operand,
            _ => throw Error(unary.Line, $"type mismatch: {unary.Op} cannot be applied to {operand}"),
        };
    }

    private KrlType Binary(KrlBinary binary)
    {
        KrlType left = Expr(binary.Left, null);
        KrlType right = Expr(binary.Right, null);
        switch (binary.Op)
        {
            case "+" or "-" or "*" or "/" when left.IsNumber && right.IsNumber:
                return left.Kind == KrlKind.Int && right.Kind == KrlKind.Int ? KrlType.Int : KrlType.Real;
            case "AND" or "OR" or "EXOR" when left.Kind == KrlKind.Bool && right.Kind == KrlKind.Bool:
                return KrlType.Bool;
            case "B_AND" or "B_OR" or "B_EXOR" when left.Kind == KrlKind.Int && right.Kind == KrlKind.Int:
                return KrlType.Int;
            case "==" or "<>" when (left.IsNumber && right.IsNumber) || (left.Kind == right.Kind && left.Kind is KrlKind.Bool or KrlKind.Char or KrlKind.Enum):
                return KrlType.Bool;
            case "<" or "<=" or ">" or ">=" when (left.IsNumber && right.IsNumber) || (left.Kind == KrlKind.Char && right.Kind == KrlKind.Char):
                return KrlType.Bool;
            default:
                throw Error(binary.Line, $"type mismatch: {left} {binary.Op} {right} is not defined in KRL");
        }
    }

    private KrlType Aggregate(KrlAggregate aggregate, KrlType? expected)
    {
        KrlType? type = aggregate.TypeName is { } named ? KrlTypes.Find(named) : expected;
        if (type is null || type.Kind != KrlKind.Struct)
        {
            throw Error(aggregate.Line, aggregate.TypeName is null
                ? "this aggregate needs a structure type: write {TYPE: …} or assign it to a structure"
                : $"unknown structure type {aggregate.TypeName}");
        }
        var indexes = new int[aggregate.Fields.Count];
        for (int i = 0; i < aggregate.Fields.Count; i++)
        {
            (string field, KrlExpr value) = aggregate.Fields[i];
            indexes[i] = type.FieldIndex(field);
            if (indexes[i] < 0)
            {
                throw Error(aggregate.Line, $"{type} has no component {field}");
            }
            if (indexes[..i].Contains(indexes[i]))
            {
                throw Error(aggregate.Line, $"the component {field} is given twice");
            }
            Require(type.Fields[indexes[i]].Type, value, $"the component {field} of {type}");
        }
        aggregate.FieldIndexes = indexes;
        return type;
    }

    /// <summary>Binds a call; returns the function's type (null for a subprogram).</summary>
    private KrlType? Call(KrlCall call, bool statement)
    {
        KrlRoutine? routine = FindRoutine(modules, _module, call.Name);
        KrlType? returns;
        if (routine is not null)
        {
            call.Routine = routine;
            returns = routine.ReturnType;
            if (call.Arguments.Count != routine.Parameters.Count)
            {
                throw Error(call.Line, $"{routine.Name} takes {routine.Parameters.Count} argument(s), not {call.Arguments.Count}");
            }
            for (int i = 0; i < call.Arguments.Count; i++)
            {
                Argument(call, i, routine.Parameters[i].Type, routine.Parameters[i].IsOut);
            }
        }
        else if (environment.Builtins.TryGetValue(call.Name, out KrlBuiltin? builtin))
        {
            call.Builtin = builtin;
            returns = builtin.Returns;
            int required = builtin.Parameters.Count(p => !p.Optional);
            if (call.Arguments.Count < required || call.Arguments.Count > builtin.Parameters.Length)
            {
                throw Error(call.Line, $"{builtin.Name} takes {builtin.Parameters.Length} argument(s), not {call.Arguments.Count}");
            }
            for (int i = 0; i < call.Arguments.Count; i++)
            {
                Argument(call, i, builtin.Parameters[i].Accepts, builtin.Parameters[i].IsOut);
            }
        }
        else
        {
            throw Error(call.Line, KrlUnsupported.Routine(call.Name) ?? $"unknown routine {call.Name}: no DEF or DEFFCT of that name in the loaded files, and not a system function");
        }
        if (!statement && returns is null)
        {
            throw Error(call.Line, $"{call.Name} is a subprogram (DEF); it has no value to use in an expression");
        }
        return returns;
    }

    private void Argument(KrlCall call, int i, KrlType? accepts, bool isOut)
    {
        KrlExpr argument = call.Arguments[i];
        if (argument is KrlOmitted)
        {
            if (call.Builtin is not null && !call.Builtin.Parameters[i].Optional)
            {
                throw Error(argument.Line, $"argument {i + 1} of {call.Name} cannot be left out on the twin");
            }
            return;
        }
        KrlType actual = isOut ? Place(argument, $"passed as OUT argument {i + 1} of {call.Name}") : Expr(argument, accepts);
        if (accepts is null)
        {
            return;
        }
        bool ok = accepts.Kind == KrlKind.Array && accepts.Element!.Kind == KrlKind.Char
            ? actual.IsText || (actual.Kind == KrlKind.Array && actual.Element!.Kind == KrlKind.Char && accepts.Sizes.Count == actual.Sizes.Count)
            : accepts.Kind == KrlKind.Array
                ? actual.Kind == KrlKind.Array && actual.Element == accepts.Element
                : KrlTypes.Assignable(accepts, actual) && (!isOut || accepts.Kind == actual.Kind || (KrlTypes.IsCartesian(accepts) && KrlTypes.IsCartesian(actual)) || (KrlTypes.IsAxes(accepts) && KrlTypes.IsAxes(actual)));
        if (!ok)
        {
            throw Error(argument.Line, $"type mismatch: argument {i + 1} of {call.Name} must be a {accepts}, not {actual}");
        }
    }
}
