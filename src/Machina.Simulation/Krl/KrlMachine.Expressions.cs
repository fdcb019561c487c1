namespace Machina.Simulation.Krl;

/// <summary>Values, places and calls.</summary>
internal sealed partial class KrlMachine
{
    /// <summary>The value of <paramref name="expr"/> in <paramref name="frame"/>.</summary>
    public object Eval(KrlExpr expr, object[] frame)
    {
        switch (expr)
        {
            case KrlLiteral literal:
                return literal.Value;
            case KrlName name:
                return name.Slot >= 0 ? frame[name.Slot] ?? LocalValue(frame, name) : name.Cell!.Value;
            case KrlMember member:
                return ((KrlStructValue)Eval(member.Target, frame)).Values[member.FieldIndex];
            case KrlIndex index when index.Each.Length == 0:
                return Eval(index.Target, frame);
            case KrlIndex { Target: KrlName { Cell.Signals: { } signals } } index when index.Each[^1] is not null:
                return signals.Get(Flat(index, signals.Type, signals.Type.Length, frame));
            case KrlIndex { Target: KrlName } index when index.Each[^1] is not null:
            {
                var array = (KrlArrayValue)Eval(index.Target, frame);
                return array.Items[Flat(index, array.Type, array.Items.Length, frame)];
            }
            case KrlIndex index:
                return Place(index, frame).Get();
            case KrlCall call:
                if (!WritesNothingWatched(call))
                {
                    _writes++;
                }
                CheckStack();
                return Call(call, frame)!;
            case KrlUnary unary:
                CheckStack();
                object operand = Eval(unary.Operand, frame);
                return unary.Op switch
                {
                    "NOT" => KrlValues.Box(!(bool)operand),
                    "B_NOT" => ~(int)operand,
                    _ => operand is int i ? -i : -(double)operand,
                };
            case KrlBinary binary:
                CheckStack();
                return Binary(binary, Eval(binary.Left, frame), Eval(binary.Right, frame));
            case KrlAggregate aggregate:
            {
                var values = new object[aggregate.Fields.Count];
                for (int i = 0; i < values.Length; i++)
                {
                    KrlType field = aggregate.Type.Fields[aggregate.FieldIndexes[i]].Type;
                    values[i] = KrlConvert.To(field, Eval(aggregate.Fields[i].Value, frame), null);
                }
                return new KrlPartialValue(aggregate.Type, aggregate.FieldIndexes, values);
            }
            default:
                throw new KrlRuntimeException("an expression the twin cannot evaluate");
        }
    }

    /// <summary>A structure or array local read before anything was stored in it: its initial value, made now and kept.</summary>
    private static object LocalValue(object[] frame, KrlName name) => frame[name.Slot] = KrlValues.Default(name.Type);

    /// <summary>Where <paramref name="expr"/> (a variable, element, row or component) is stored.</summary>
    public KrlPlace Place(KrlExpr expr, object[] frame)
    {
        switch (expr)
        {
            case KrlName name when name.Slot >= 0:
                frame[name.Slot] ??= KrlValues.Default(name.Type);
                return new KrlPlace(frame, name.Slot, name.Type);
            case KrlName { Cell.Signals: { } signals } name:
                return new KrlPlace([], -1, name.Type) { Root = (name.Cell, -1), Signals = signals };
            case KrlName name:
                return new KrlPlace(name.Cell!.Box, 0, name.Type) { Root = (name.Cell, -1) };
            case KrlMember member:
            {
                KrlPlace parent = Place(member.Target, frame);
                var structure = (KrlStructValue)parent.Container[parent.Index];
                if (structure.Shared)
                {
                    // A status the EKI_ functions hand out to every caller: the variable gets its own copy before a component changes.
                    structure = structure.Copy();
                    parent.Container[parent.Index] = structure;
                }
                return new KrlPlace(structure.Values, member.FieldIndex, member.Type) { Root = parent.Root is { } r ? (r.Cell, -1) : null, Structure = structure };
            }
            case KrlIndex { Target: KrlName name } index when index.Each.Length > 0 && name.Cell?.Signals is null:
            {
                // An element or row of a variable (the driver's OUT arguments slot_v[write_slot, 1] …, nine an action): the
                // variable's array as its place would hold it, without making that place first.
                KrlArrayValue array;
                KrlCell? cell = null;
                if (name.Slot >= 0)
                {
                    array = (KrlArrayValue)(frame[name.Slot] ??= KrlValues.Default(name.Type));
                }
                else
                {
                    cell = name.Cell!;
                    array = (KrlArrayValue)cell.Box[0];
                }
                return ElementPlace(index, array, cell, frame);
            }
            case KrlIndex index:
            {
                KrlPlace parent = Place(index.Target, frame);
                if (index.Each.Length == 0)
                {
                    return parent;
                }
                if (parent.Signals is { } signals)
                {
                    if (index.Each[^1] is null)
                    {
                        return parent;
                    }
                    int element = Flat(index, signals.Type, signals.Type.Length, frame);
                    return new KrlPlace([], element, index.Type) { Root = (parent.Root!.Value.Cell, element), Signals = signals };
                }
                return ElementPlace(index, (KrlArrayValue)parent.Container[parent.Index], parent.Root?.Cell, frame);
            }
            default:
                throw new KrlRuntimeException("only a variable can be written");
        }
    }

    /// <summary>The element (or, with the last index left out, the row) of <paramref name="array"/> that <paramref name="index"/> selects; <paramref name="cell"/> is the variable it is part of (null for a local).</summary>
    private KrlPlace ElementPlace(KrlIndex index, KrlArrayValue array, KrlCell? cell, object[] frame)
    {
        int[] sizes = array.Type.Dimensions;
        KrlExpr?[] indices = index.Each;
        int flat = 0;
        for (int d = 0; d < indices.Length; d++)
        {
            int size = sizes[d] == 0 ? array.Items.Length : sizes[d];
            int i = indices[d] is { } e ? KrlValues.ToInt(Eval(e, frame)) : 1;
            if (i < 1 || i > size)
            {
                throw new KrlRuntimeException($"Array index inadmissible: index {i} of {Describe(index.Target)} is outside 1 to {size}");
            }
            flat = flat * size + (i - 1);
        }
        if (indices[^1] is null)
        {
            return new KrlPlace(array.Items, flat, index.Type, sizes[^1]) { Root = cell is null ? null : (cell, -1) };
        }
        return new KrlPlace(array.Items, flat, index.Type) { Root = cell is null ? null : (cell, flat) };
    }

    /// <summary>
    /// True when a call cannot write what an interrupt's condition reads: a built-in that writes only its OUT arguments (see
    /// <see cref="KrlBuiltin.WritesOnlyArguments"/>), each of them a local or a variable no condition reads, while no condition
    /// reads locals or calls a function. Any other call makes the interpreter look at the conditions again.
    /// </summary>
    private bool WritesNothingWatched(KrlCall call)
    {
        if (_watchesAll || call.Builtin is not { WritesOnlyArguments: true } builtin)
        {
            return false;
        }
        KrlExpr[] arguments = call.Each;
        for (int i = 0; i < arguments.Length; i++)
        {
            if (builtin.Parameters[i].IsOut && !LocalOrUnwatched(arguments[i]))
            {
                return false;
            }
        }
        return true;
    }

    /// <summary>True when <paramref name="place"/> is (part of) a local, or of a variable that is neither watched nor an IO array.</summary>
    private static bool LocalOrUnwatched(KrlExpr place) => place switch
    {
        KrlName { Slot: >= 0 } => true,
        KrlName { Cell: { Watched: false, Signals: null } } => true,
        KrlIndex index => LocalOrUnwatched(index.Target),
        KrlMember member => LocalOrUnwatched(member.Target),
        KrlOmitted => true,
        _ => false,
    };

    /// <summary>Stores <paramref name="value"/> in <paramref name="target"/> (locals and plain array elements without a place object).</summary>
    private void Assign(KrlExpr target, object value, object[] frame)
    {
        switch (target)
        {
            case KrlName { Slot: >= 0 } local:
                frame[local.Slot] = KrlConvert.To(local.Type, value, frame[local.Slot]);
                return;
            case KrlIndex { Target: KrlName { Slot: >= 0 } or KrlName { Cell.Written: null } } index when index.Each.Length > 0 && index.Each[^1] is not null:
            {
                var array = (KrlArrayValue)Eval(index.Target, frame);
                int flat = Flat(index, array.Type, array.Items.Length, frame);
                array.Items[flat] = KrlConvert.To(index.Type, value, array.Items[flat]);
                if (_watchesAll || index.Target is not KrlName { Cell.Watched: false })
                {
                    _writes++; // the driver's FOR over a ring slot's 80 characters wrote unwatched data: 3 conditions per character
                    (index.Target as KrlName)?.Cell?.CountWrite();
                }
                else if (index.Target is KrlName { Cell.WakesOnWrite: true } woken)
                {
                    woken.Cell!.CountWrite(); // a WAIT FOR's condition reads it: a waiting WAIT FOR (the other interpreter's) wakes
                }
                return;
            }
            case KrlMember { Target: KrlName { Slot: >= 0 } local } member:
            {
                // A component of a local structure (the driver's target.X = … and pose.X = …, twelve an action): what its place
                // would do, without making the place.
                var structure = (KrlStructValue)(frame[local.Slot] ??= KrlValues.Default(local.Type));
                if (structure.Shared)
                {
                    structure = structure.Copy();
                    frame[local.Slot] = structure;
                }
                int field = member.FieldIndex;
                structure.Values[field] = KrlConvert.To(member.Type, value, structure.Values[field]);
                structure.Give(field);
                if (_watchesAll || _watchesComputed)
                {
                    _writes++;
                }
                return;
            }
            default:
                Place(target, frame).Set(value);
                if (_watchesAll || _watchesComputed || !LocalOrUnwatched(target))
                {
                    // A variable an interrupt's condition reads (or any write, when a condition reads locals, calls a function or
                    // reads a computed variable): the conditions are looked at before the next statement. The driver's ring
                    // counters and components of its local FRAMEs are written ~10 times an action and no condition reads them.
                    _writes++;
                }
                return;
        }
    }

    /// <summary>The element of an array of <paramref name="type"/> and <paramref name="length"/> elements that the (complete) indices of <paramref name="index"/> select.</summary>
    private int Flat(KrlIndex index, KrlType type, int length, object[] frame)
    {
        int[] sizes = type.Dimensions;
        KrlExpr?[] indices = index.Each;
        int flat = 0;
        for (int d = 0; d < indices.Length; d++)
        {
            int size = sizes[d] == 0 ? length : sizes[d];
            int i = KrlValues.ToInt(Eval(indices[d]!, frame));
            if (i < 1 || i > size)
            {
                throw new KrlRuntimeException($"Array index inadmissible: index {i} of {Describe(index.Target)} is outside 1 to {size}");
            }
            flat = flat * size + (i - 1);
        }
        return flat;
    }

    private static string Describe(KrlExpr expr) => expr switch
    {
        KrlName n => n.Name,
        KrlMember m => Describe(m.Target) + "." + m.Field,
        _ => "the array",
    };

    /// <summary>Calls a routine or a built-in; returns a function's value (null for a subprogram).</summary>
    public object? Call(KrlCall call, object[] frame)
    {
        KrlExpr[] given = call.Each;
        object[] arguments = BorrowArguments(given.Length, out Borrowed mark);
        try
        {
            for (int i = 0; i < arguments.Length; i++)
            {
                bool isOut = call.Routine is { } r ? r.Parameters[i].IsOut : call.Builtin!.Parameters[i].IsOut;
                KrlExpr argument = given[i];
                arguments[i] = argument is KrlOmitted ? null! : isOut ? BoxPlace(Place(argument, frame)) : Eval(argument, frame);
            }
            if (call.Routine is { } routine)
            {
                return Invoke(routine, arguments);
            }
            int line = Line;
            object? result = call.Builtin!.Run(this, arguments);
            Line = line;
            return result;
        }
        finally
        {
            GiveBack(mark);
        }
    }

    private static object Binary(KrlBinary binary, object left, object right)
    {
        int code = binary.Code;
        switch (code)
        {
            case 4:
                return KrlValues.Box((bool)left && (bool)right);
            case 5:
                return KrlValues.Box((bool)left || (bool)right);
            case 6:
                return KrlValues.Box((bool)left ^ (bool)right);
            case 7:
                return (int)left & (int)right;
            case 8:
                return (int)left | (int)right;
            case 9:
                return (int)left ^ (int)right;
            case 10:
                return KrlValues.Box(Equal(left, right));
            case 11:
                return KrlValues.Box(!Equal(left, right));
        }
        if (left is char cl && right is char cr)
        {
            return KrlValues.Box(Compare(code, cl.CompareTo(cr)));
        }
        if (left is int a && right is int b)
        {
            return code switch
            {
                0 => KrlValues.Box(a + b),
                1 => KrlValues.Box(a - b),
                2 => KrlValues.Box(a * b),
                3 => b == 0 ? throw new KrlRuntimeException("Division by 0")
                    : a == int.MinValue && b == -1 ? throw new KrlRuntimeException("Arithmetic overflow: -2147483648 / -1 is not an INT")
                    : KrlValues.Box(a / b),
                _ => KrlValues.Box(Compare(code, a.CompareTo(b))),
            };
        }
        double x = KrlValues.ToReal(left), y = KrlValues.ToReal(right);
        return code switch
        {
            0 => x + y,
            1 => x - y,
            2 => x * y,
            3 => y == 0 ? throw new KrlRuntimeException("Division by 0") : x / y,
            _ => KrlValues.Box(Compare(code, x.CompareTo(y))),
        };
    }

    private static bool Compare(int code, int sign) => code switch
    {
        12 => sign < 0,
        13 => sign <= 0,
        14 => sign > 0,
        _ => sign >= 0,
    };

    /// <summary>KRL's == : numbers by value (INT against REAL too), the rest by equality.</summary>
    public static bool Equal(object left, object right) => left switch
    {
        int a when right is int b => a == b,
        int or double when right is int or double => KrlValues.ToReal(left) == KrlValues.ToReal(right),
        _ => left.Equals(right),
    };
}
