namespace Machina.Simulation.UrScript;

/// <summary>An expression of a URScript program, with the line it is on.</summary>
internal abstract class UrExpr(int line)
{
    /// <summary>The 1-based line of the program.</summary>
    public int Line { get; } = line;

    /// <summary>The value of the expression in <paramref name="frame"/>.</summary>
    public abstract object Eval(UrFrame frame);

    /// <summary>
    /// The value as a number (<see cref="UrValue.Number"/> of <see cref="Eval"/>, with its error naming <paramref name="what"/> at
    /// <paramref name="line"/>); arithmetic gives it without boxing.
    /// </summary>
    public virtual double EvalNumber(UrFrame frame, int line, string what) => UrValue.Number(Eval(frame), line, what);
}

/// <summary>A literal number, bool or string.</summary>
internal sealed class UrConst(int line, object value) : UrExpr(line)
{
    /// <summary>The constant value.</summary>
    public object Value { get; } = value;

    /// <inheritdoc/>
    public override object Eval(UrFrame frame) => Value;
}

/// <summary>A list literal <c>[a, b, ...]</c> (a new list each time it is evaluated).</summary>
internal sealed class UrListExpr(int line, UrExpr[] items) : UrExpr(line)
{
    /// <summary>The element expressions.</summary>
    public UrExpr[] Items { get; } = items;

    /// <inheritdoc/>
    public override object Eval(UrFrame frame)
    {
        var values = new object[Items.Length];
        for (int i = 0; i < values.Length; i++)
        {
            values[i] = Items[i].Eval(frame);
        }
        return new UrList(values);
    }
}

/// <summary>A pose literal <c>p[x, y, z, rx, ry, rz]</c>.</summary>
internal sealed class UrPoseExpr(int line, UrExpr[] items) : UrExpr(line)
{
    /// <summary>The six element expressions.</summary>
    public UrExpr[] Items { get; } = items;

    /// <inheritdoc/>
    public override object Eval(UrFrame frame)
    {
        var values = new double[6];
        for (int i = 0; i < 6; i++)
        {
            values[i] = Items[i].EvalNumber(frame, Line, "a pose element");
        }
        return new UrPose(values);
    }
}

/// <summary>A variable; the binder resolves it to a local or global slot.</summary>
internal sealed class UrName(int line, string name) : UrExpr(line)
{
    /// <summary>The variable's name.</summary>
    public string Name { get; } = name;

    /// <summary>True when the variable is a local of the enclosing function.</summary>
    public bool IsLocal { get; set; }

    /// <summary>The slot in the locals or the globals.</summary>
    public int Slot { get; set; } = -1;

    /// <inheritdoc/>
    public override object Eval(UrFrame frame) =>
        (IsLocal ? frame.Locals[Slot] : frame.Machine.Globals[Slot])
        ?? throw new UrRuntimeException(Line, $"variable '{Name}' is used before it is assigned");

    /// <summary>Stores <paramref name="value"/> in the variable.</summary>
    public void Assign(UrFrame frame, object value)
    {
        if (IsLocal)
        {
            frame.Locals[Slot] = value;
        }
        else
        {
            frame.Machine.Globals[Slot] = value;
        }
    }
}

/// <summary>An element of a list or pose: <c>a[i]</c> (0-based).</summary>
internal sealed class UrIndex(int line, UrExpr target, UrExpr index) : UrExpr(line)
{
    /// <summary>The list or pose.</summary>
    public UrExpr Target { get; } = target;

    /// <summary>The index.</summary>
    public UrExpr Index { get; } = index;

    /// <inheritdoc/>
    public override object Eval(UrFrame frame)
    {
        UrStack.Check(frame, Line);
        object target = Target.Eval(frame);
        int i = UrValue.Int(Index.Eval(frame), Line, "an index");
        return target switch
        {
            UrList list when i >= 0 && i < list.Items.Length => list.Items[i],
            UrPose pose when i >= 0 && i < 6 => pose.Values[i],
            UrList or UrPose => throw new UrRuntimeException(Line, $"index {i} is out of range (length {(target is UrList l ? l.Items.Length : 6)})"),
            _ => throw new UrRuntimeException(Line, $"only an array or a pose can be indexed, not {UrValue.TypeName(target)}"),
        };
    }

    /// <summary>Stores <paramref name="value"/> at the index.</summary>
    public void Assign(UrFrame frame, object value)
    {
        object target = Target.Eval(frame);
        int i = UrValue.Int(Index.Eval(frame), Line, "an index");
        switch (target)
        {
            case UrList list when i >= 0 && i < list.Items.Length:
                list.Items[i] = value;
                break;
            case UrPose pose when i >= 0 && i < 6:
                pose.Values[i] = UrValue.Number(value, Line, "a pose element");
                break;
            default:
                throw new UrRuntimeException(Line, $"index {i} is out of range or {UrValue.TypeName(target)} cannot be indexed");
        }
    }
}

/// <summary><c>-x</c> or <c>not x</c>.</summary>
internal sealed class UrUnary(int line, string op, UrExpr operand) : UrExpr(line)
{
    /// <summary>The operand.</summary>
    public UrExpr Operand { get; } = operand;

    /// <inheritdoc/>
    public override object Eval(UrFrame frame)
    {
        UrStack.Check(frame, Line);
        object value = Operand.Eval(frame);
        if (op == "not")
        {
            return UrValue.Box(!UrValue.Bool(value, Line, "the operand of 'not'"));
        }
        return value switch
        {
            int i => -i,
            double d => -d,
            UrPose p => new UrPose(p.Values.Select(v => -v).ToArray()),
            UrList l => new UrList([.. l.Items.Select(v => v switch
            {
                int i => (object)-i,
                double d => -d,
                _ => throw new UrRuntimeException(Line, $"'-' cannot be applied to an array of {UrValue.TypeName(v)}"),
            })]),
            _ => throw new UrRuntimeException(Line, $"'-' cannot be applied to {UrValue.TypeName(value)}"),
        };
    }
}

/// <summary><c>a and b</c>, <c>a or b</c> (the right side is evaluated only when needed).</summary>
internal sealed class UrLogical(int line, bool isAnd, UrExpr left, UrExpr right) : UrExpr(line)
{
    /// <summary>The left operand.</summary>
    public UrExpr Left { get; } = left;

    /// <summary>The right operand.</summary>
    public UrExpr Right { get; } = right;

    /// <inheritdoc/>
    public override object Eval(UrFrame frame)
    {
        UrStack.Check(frame, Line);
        bool l = UrValue.Bool(Left.Eval(frame), Line, isAnd ? "the operand of 'and'" : "the operand of 'or'");
        if (isAnd ? !l : l)
        {
            return UrValue.Box(l);
        }
        return UrValue.Box(UrValue.Bool(Right.Eval(frame), Line, isAnd ? "the operand of 'and'" : "the operand of 'or'"));
    }
}
