namespace Machina.Simulation.Krl;

/// <summary>Values, places and calls.</summary>
internal sealed partial class KrlMachine
{
    /// <summary>The value of <paramref name="expr"/> in <paramref name="frame"/>.</summary>
    public object Eval(KrlExpr expr, object[] frame)
    {
        switch (expr.Node)
        {
            case KrlNode.Literal:
                return ((KrlLiteral)expr).Value;
            case KrlNode.Name:
            {
                var name = (KrlName)expr;
                return name.Slot >= 0 ? frame[name.Slot] ?? LocalValue(frame, name) : name.Cell!.Value;
            }
            case KrlNode.Member:
            {
                var member = (KrlMember)expr;
                return ((KrlStructValue)Eval(member.Target, frame)).Values[member.FieldIndex];
            }
            case KrlNode.Index:
                return Element((KrlIndex)expr, frame);
            case KrlNode.Call:
            {
                var call = (KrlCall)expr;
                if (!WritesNothingWatched(call))
                {
                    _writes++;
                }
                CheckStack();
                return Call(call, frame)!;
            }
            case KrlNode.Unary:
            {
                var unary = (KrlUnary)expr;
                CheckStack();
                object operand = Eval(unary.Operand, frame);
                return unary.Op switch
                {
                    "NOT" => KrlValues.Box(!(bool)operand),
                    "B_NOT" => ~(int)operand,
                    _ => operand is int i ? -i : -(double)operand,
                };
            }
            case KrlNode.Binary:
            {
                // Typed: the operands and any operation under them are evaluated without a box per intermediate value.
                var binary = (KrlBinary)expr;
                return binary.Type.Kind switch
                {
                    KrlKind.Real => (object)RealBinary(binary, frame),
                    KrlKind.Bool => KrlValues.Box(BoolBinary(binary, frame)),
                    _ => KrlValues.Box(IntBinary(binary, frame)),
                };
            }
            case KrlNode.Aggregate:
            {
                var aggregate = (KrlAggregate)expr;
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

    /// <summary>The value of an element, a row or a whole array (<see cref="KrlIndex.Access"/> says which, fixed by the binder).</summary>
    private object Element(KrlIndex index, object[] frame)
    {
        switch (index.Access)
        {
            case KrlAccess.Element:
            {
                KrlArrayValue array = ElementArray(index, frame);
                return array[Flat(index, array.Type, array.Length, frame)];
            }
            case KrlAccess.Signal:
            {
                KrlSignalArray signals = ((KrlName)index.Target).Cell!.Signals!;
                return signals.Get(Flat(index, signals.Type, signals.Type.Length, frame));
            }
            case KrlAccess.Whole:
                return Eval(index.Target, frame);
            default:
                return Place(index, frame).Get();
        }
    }

    /// <summary>The array variable or local an element read (<see cref="KrlAccess.Element"/>) indexes.</summary>
    private KrlArrayValue ElementArray(KrlIndex index, object[] frame)
    {
        var name = (KrlName)index.Target;
        return (KrlArrayValue)(name.Slot >= 0 ? frame[name.Slot] ?? LocalValue(frame, name) : name.Cell!.Value);
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
                var structure = (KrlStructValue)parent.Value;
                if (structure.Shared)
                {
                    // A status the EKI_ functions hand out to every caller: the variable gets its own copy before a component changes.
                    structure = structure.Copy();
                    parent.Replace(structure);
                }
                return new KrlPlace([], member.FieldIndex, member.Type) { Root = parent.Root is { } r ? (r.Cell, -1) : null, Structure = structure };
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
                return ElementPlace(index, (KrlArrayValue)parent.Value, parent.Root?.Cell, frame);
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
            int size = sizes[d] == 0 ? array.Length : sizes[d];
            int i = indices[d] is { } e ? IntOf(e, frame) : 1;
            if (i < 1 || i > size)
            {
                throw new KrlRuntimeException($"Array index inadmissible: index {i} of {Describe(index.Target)} is outside 1 to {size}");
            }
            flat = flat * size + (i - 1);
        }
        object[] container = array.HoldsReals ? [] : array.Objects;
        KrlArrayValue? reals = array.HoldsReals ? array : null;
        if (indices[^1] is null)
        {
            return new KrlPlace(container, flat, index.Type, sizes[^1]) { Root = cell is null ? null : (cell, -1), Reals = reals };
        }
        return new KrlPlace(container, flat, index.Type) { Root = cell is null ? null : (cell, flat), Reals = reals };
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

    /// <summary>After an element of an array variable or local was written: the conditions are looked at again when one reads it, a waiting WAIT FOR on it wakes.</summary>
    private void ElementWritten(KrlIndex index)
    {
        if (_watchesAll || index.Target is not KrlName { Cell.Watched: false })
        {
            _writes++; // the driver's FOR over a ring slot's 80 characters wrote unwatched data: 3 conditions per character
            (index.Target as KrlName)?.Cell?.CountWrite();
        }
        else if (index.Target is KrlName { Cell.WakesOnWrite: true } woken)
        {
            woken.Cell!.CountWrite(); // a WAIT FOR's condition reads it: a waiting WAIT FOR (the other interpreter's) wakes
        }
    }

    /// <summary>Stores <paramref name="value"/> in the target of <paramref name="assign"/> (locals, plain array elements and local components without a place object).</summary>
    private void Assign(KrlAssign assign, object value, object[] frame)
    {
        KrlExpr target = assign.Target;
        switch (assign.Store)
        {
            case KrlStore.Local:
            {
                var local = (KrlName)target;
                frame[local.Slot] = KrlConvert.To(local.Type, value, frame[local.Slot]);
                return;
            }
            case KrlStore.Element:
            {
                var index = (KrlIndex)target;
                var array = (KrlArrayValue)Eval(index.Target, frame);
                int flat = Flat(index, array.Type, array.Length, frame);
                if (array.HoldsReals)
                {
                    array.SetReal(flat, KrlValues.ToReal(value));
                }
                else
                {
                    object[] items = array.Objects;
                    items[flat] = KrlConvert.To(index.Type, value, items[flat]);
                }
                ElementWritten(index);
                return;
            }
            case KrlStore.LocalMember:
            {
                var member = (KrlMember)target;
                var local = (KrlName)member.Target;
                // A component of a local structure (the driver's target.X = … and pose.X = …, twelve an action): what its place
                // would do, without making the place.
                KrlStructValue structure = LocalStructure(member, frame);
                int field = member.FieldIndex;
                structure.Values[field] = KrlConvert.To(member.Type, value, member.Type.Kind is KrlKind.Struct or KrlKind.Array ? structure.Values[field] : null);
                LocalComponentWritten(structure, field);
                return;
            }
            case KrlStore.Cell:
            {
                // A data list's or system variable (the driver's ring counters, machina_running, last_executed: eight an action):
                // what its place would do, without making the place.
                var name = (KrlName)target;
                KrlCell cell = name.Cell!;
                object[] box = cell.Box;
                box[0] = KrlConvert.To(name.Type, value, box[0]);
                cell.CountWrite();
                cell.Written?.Invoke(-1);
                if (_watchesAll || _watchesComputed || cell.Watched)
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
            int i = IntOf(indices[d]!, frame);
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
                return Invoke(routine, arguments, call.SharedArguments);
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
