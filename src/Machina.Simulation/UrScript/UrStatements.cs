namespace Machina.Simulation.UrScript;

/// <summary>How a statement ended.</summary>
internal enum UrFlow
{
    /// <summary>Go on with the next statement.</summary>
    Next,

    /// <summary><c>break</c>.</summary>
    Break,

    /// <summary><c>continue</c>.</summary>
    Continue,

    /// <summary><c>return</c>.</summary>
    Return,
}

/// <summary>A statement of a URScript program, with the line it is on.</summary>
internal abstract class UrStmt(int line)
{
    /// <summary>The 1-based line of the program.</summary>
    public int Line { get; } = line;

    /// <summary>Runs the statement.</summary>
    public abstract UrFlow Exec(UrFrame frame);

    /// <summary>Runs statements in order until one breaks, continues or returns.</summary>
    public static UrFlow Run(List<UrStmt> block, UrFrame frame)
    {
        for (int i = 0; i < block.Count; i++)
        {
            UrStmt statement = block[i];
            frame.Machine.Step(statement.Line);
            UrFlow flow = statement.Exec(frame);
            if (flow != UrFlow.Next)
            {
                return flow;
            }
        }
        return UrFlow.Next;
    }
}

/// <summary><c>name = value</c> or <c>name[i] = value</c>.</summary>
internal sealed class UrAssign(int line, UrExpr target, UrExpr value) : UrStmt(line)
{
    /// <summary>A <see cref="UrName"/> or <see cref="UrIndex"/>.</summary>
    public UrExpr Target { get; } = target;

    /// <summary>The assigned value.</summary>
    public UrExpr Value { get; } = value;

    /// <inheritdoc/>
    public override UrFlow Exec(UrFrame frame)
    {
        object value = Value.Eval(frame);
        if (Target is UrName name)
        {
            name.Assign(frame, value);
        }
        else
        {
            ((UrIndex)Target).Assign(frame, value);
        }
        return UrFlow.Next;
    }
}

/// <summary>An expression used as a statement (a call).</summary>
internal sealed class UrExprStmt(int line, UrExpr expr) : UrStmt(line)
{
    /// <summary>The expression.</summary>
    public UrExpr Expr { get; } = expr;

    /// <inheritdoc/>
    public override UrFlow Exec(UrFrame frame)
    {
        Expr.Eval(frame);
        return UrFlow.Next;
    }
}

/// <summary><c>if … elif … else … end</c>.</summary>
internal sealed class UrIf(int line, List<(UrExpr Condition, List<UrStmt> Body)> branches, List<UrStmt>? otherwise) : UrStmt(line)
{
    /// <summary>The conditions and their blocks, in order.</summary>
    public List<(UrExpr Condition, List<UrStmt> Body)> Branches { get; } = branches;

    /// <summary>The <c>else</c> block.</summary>
    public List<UrStmt>? Otherwise { get; } = otherwise;

    /// <inheritdoc/>
    public override UrFlow Exec(UrFrame frame)
    {
        foreach ((UrExpr condition, List<UrStmt> body) in Branches)
        {
            if (UrValue.Bool(condition.Eval(frame), condition.Line, "an if condition"))
            {
                return Run(body, frame);
            }
        }
        return Otherwise is null ? UrFlow.Next : Run(Otherwise, frame);
    }
}

/// <summary><c>while condition: … end</c>.</summary>
internal sealed class UrWhile(int line, UrExpr condition, List<UrStmt> body) : UrStmt(line)
{
    /// <summary>The loop condition.</summary>
    public UrExpr Condition { get; } = condition;

    /// <summary>The loop body.</summary>
    public List<UrStmt> Body { get; } = body;

    /// <inheritdoc/>
    public override UrFlow Exec(UrFrame frame)
    {
        while (UrValue.Bool(Condition.Eval(frame), Line, "a while condition"))
        {
            frame.Machine.LoopTick();
            UrFlow flow = Run(Body, frame);
            if (flow == UrFlow.Break)
            {
                break;
            }
            if (flow == UrFlow.Return)
            {
                return flow;
            }
        }
        return UrFlow.Next;
    }
}

/// <summary><c>break</c>, <c>continue</c>, <c>return [value]</c>.</summary>
internal sealed class UrJump(int line, UrFlow flow, UrExpr? value) : UrStmt(line)
{
    /// <summary>What the jump does.</summary>
    public UrFlow Flow { get; } = flow;

    /// <summary>The returned value, if any.</summary>
    public UrExpr? Value { get; } = value;

    /// <inheritdoc/>
    public override UrFlow Exec(UrFrame frame)
    {
        if (Value is not null)
        {
            frame.ReturnValue = Value.Eval(frame);
        }
        return Flow;
    }
}

/// <summary><c>halt</c>: ends the program.</summary>
internal sealed class UrHalt(int line) : UrStmt(line)
{
    /// <inheritdoc/>
    public override UrFlow Exec(UrFrame frame) => throw new UrHaltSignal(Line);
}

/// <summary><c>join t</c> (wait for a thread to end) or <c>kill t</c> (stop it); a handle of 0 (no thread) does nothing.</summary>
internal sealed class UrThreadControl(int line, bool kill, UrExpr handle) : UrStmt(line)
{
    /// <summary>The thread handle expression.</summary>
    public UrExpr Handle { get; } = handle;

    /// <inheritdoc/>
    public override UrFlow Exec(UrFrame frame)
    {
        object value = Handle.Eval(frame);
        if (value is 0)
        {
            return UrFlow.Next; // no thread: UR's clients start their handles at 0 and join or kill them before any thread ran
        }
        if (value is not UrThreadHandle thread)
        {
            throw new UrRuntimeException(Line, $"{(kill ? "kill" : "join")} needs a thread handle, not {UrValue.TypeName(value)}");
        }
        if (kill)
        {
            frame.Machine.KillThread(thread);
        }
        else
        {
            frame.Machine.JoinThread(thread, Line);
        }
        return UrFlow.Next;
    }
}

/// <summary>A statement that does nothing when run (a definition or a <c>global</c>/<c>local</c> declaration).</summary>
internal sealed class UrNoOp(int line) : UrStmt(line)
{
    /// <inheritdoc/>
    public override UrFlow Exec(UrFrame frame) => UrFlow.Next;
}

/// <summary>Thrown by <c>halt</c>: the program ends normally.</summary>
internal sealed class UrHaltSignal(int line) : Exception("halt")
{
    /// <summary>The line of the halt.</summary>
    public int Line { get; } = line;
}
