using System.Runtime.CompilerServices;
using Machina.Simulation.Twin;

namespace Machina.Simulation.Rapid;

/// <summary>
/// Runs the statements of one RAPID task: control flow, routine calls (parameters by value or by reference), error handlers
/// (ERRNO, RETRY, TRYNEXT, RAISE, RETURN), GOTO and labels. Built-ins act on the task's controller.
/// </summary>
internal sealed partial class RapidMachine(RapidTask task)
{
    /// <summary>The value of an optional parameter that was not given.</summary>
    internal static readonly object Absent = new();

    /// <summary>The task this machine runs.</summary>
    public RapidTask Task { get; } = task;

    private int _depth;
    private long _steps;
    private int _stackChecks;

    /// <summary>The array elements of the routines' local data now (bounded by <see cref="TwinLimits.MaxTotalElements"/>).</summary>
    private long _localElements;

    /// <summary>The interpreter's budgets.</summary>
    public TwinLimits Limits { get; } = task.Controller.Options.Limits;

    /// <summary>The step budget (<see cref="TwinLimits.MaxSteps"/>, 0: none), read at every statement.</summary>
    private readonly long _maxSteps = task.Controller.Options.Limits.MaxSteps;

    /// <summary>The error of a budget of the twin: no ERROR handler takes it, the task stops.</summary>
    internal static RapidRuntimeException Budget(int line, string message) => new(0, line, message) { Fatal = true };

    /// <summary>
    /// Throws the task's error when the running thread has too little stack left for one more level. The runtime is asked at every
    /// 8th call (<see cref="TwinLimits.StackCheckEvery"/>).
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private void CheckStack(int line)
    {
        if ((++_stackChecks & (TwinLimits.StackCheckEvery - 1)) == 0)
        {
            AskForStack(line);
        }
    }

    private static void AskForStack(int line)
    {
        if (TwinLimits.StackLow)
        {
            throw Budget(line, "stack overflow: the routine calls and expressions are nested too deeply");
        }
    }

    /// <summary>Calls a routine with no arguments (main, or a trap).</summary>
    public void Run(RapidRoutine routine) => Invoke(routine, [], new RapidCallTarget(null, routine, []), null, routine.Line);

    private RapidFlow ExecuteBlock(List<RapidStmt> body, RapidFrame frame)
    {
        int i = 0;
        while (i < body.Count)
        {
            Step(body[i].Line);
            RapidFlow flow = frame.Routine.ErrorHandler is null || frame.Handling is not null
                ? ExecuteAfterTraps(body[i], frame)
                : ExecuteGuarded(body[i], frame);
            if (flow == RapidFlow.Next)
            {
                i++;
                continue;
            }
            if (flow == RapidFlow.Goto && LabelIn(body, frame.GotoLabel!) is int target and >= 0)
            {
                frame.GotoLabel = null;
                i = target;
                continue;
            }
            return flow;
        }
        return RapidFlow.Next;
    }

    /// <summary>Counts one statement or loop turn against the step budget.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private void Step(int line)
    {
        if (++_steps > _maxSteps && _maxSteps > 0)
        {
            throw TooManySteps(line);
        }
    }

    private RapidRuntimeException TooManySteps(int line) =>
        Budget(line, $"the task ran more than {_maxSteps:N0} statements and loop turns (the verification's step budget): an endless loop?");

    private static int LabelIn(List<RapidStmt> body, string label) =>
        body.FindIndex(s => s is RapidJump { Kind: RapidJumpKind.Label } j && j.Label!.Equals(label, StringComparison.OrdinalIgnoreCase));

    /// <summary>Runs a statement of a routine that has an ERROR handler: a RAPID error in it goes to the handler.</summary>
    private RapidFlow ExecuteGuarded(RapidStmt statement, RapidFrame frame)
    {
        bool retried = false;
        while (true)
        {
            try
            {
                RapidFlow done = ExecuteAfterTraps(statement, frame);
                if (retried)
                {
                    _retries = 0; // the statement got past its error
                }
                return done;
            }
            catch (RapidRuntimeException ex) when (ex.RaisedBy != frame && frame.Handling is null && !ex.Fatal && Takes(frame, ex.ErrorNumber))
            {
                frame.Handling = ex;
                Task.Program.Errno.Value = (double)ex.ErrorNumber;
                RapidFlow flow;
                try
                {
                    flow = ExecuteBlock(frame.Routine.ErrorHandler!, frame);
                }
                catch (RapidRuntimeException inner) when (!inner.Fatal && !(ReferenceEquals(inner, ex) && inner.RaisedBy == frame))
                {
                    throw ToSystemErrorHandler(inner);
                }
                finally
                {
                    frame.Handling = null;
                }
                if (flow != RapidFlow.Retry)
                {
                    _retries = 0;
                    return flow == RapidFlow.TryNext ? RapidFlow.Next : RapidFlow.Return;
                }
                Task.CancellationToken.ThrowIfCancellationRequested();
                if (++_retries > Task.Controller.Options.MaxRetries && Task.Controller.Options.MaxRetries > 0)
                {
                    _retries = 0;
                    throw TooManyRetries(ex);
                }
                retried = true;
            }
        }
    }

    /// <summary>
    /// Serves the queued interrupts, then runs the statement: an error a trap raises (RAISE in its ERROR handler, RAPID's long jump)
    /// goes to the handler of the routine that was running, as if the statement had raised it.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private RapidFlow ExecuteAfterTraps(RapidStmt statement, RapidFrame frame)
    {
        // A stopped task stops at its next statement, as a controller's stop does at the current instruction: a task that ran on
        // after its stop accepted a client a restart had already refused, and greeted it (CI, the ABB restart trial).
        Task.CancellationToken.ThrowIfCancellationRequested();
        Task.RunPendingTraps();
        Task.Sends.Statement();
        return Execute(statement, frame);
    }

    private RapidFlow Execute(RapidStmt statement, RapidFrame frame)
    {
        // Each kind in a small method of its own: one large method made every statement pay for the locals of all kinds.
        switch (statement)
        {
            case RapidAssign a:
                if (a.Value is not RapidAggregate aggregate || !AssignInPlace(a.Target, aggregate, frame))
                {
                    Store(a.Target, frame, Evaluate(a.Value, frame), owned: a.Value is RapidAggregate);
                }
                return RapidFlow.Next;
            case RapidIf i:
                return If(i, frame);
            case RapidProcCall call:
                Call(call.Target!, call.Args, frame, call.Line);
                return RapidFlow.Next;
            case RapidTest t:
                return Test(t, frame);
            case RapidWhile w:
                return While(w, frame);
            case RapidFor f:
                return For(f, frame);
            case RapidJump j:
                return Jump(j, frame);
            case RapidLateCall late:
                Call(LateTarget(late, frame), late.Args, frame, late.Line);
                return RapidFlow.Next;
            case RapidConnect c:
                Store(c.Interrupt, frame, (double)Task.Connect(c.Routine!));
                return RapidFlow.Next;
            default:
                throw new InvalidOperationException($"Unknown statement {statement.GetType().Name}.");
        }
    }

    private RapidFlow If(RapidIf i, RapidFrame frame)
    {
        List<(RapidExpr Condition, List<RapidStmt> Body)> branches = i.Branches;
        for (int k = 0; k < branches.Count; k++)
        {
            if (Condition(branches[k].Condition, frame))
            {
                return ExecuteBlock(branches[k].Body, frame);
            }
        }
        return i.Otherwise is null ? RapidFlow.Next : ExecuteBlock(i.Otherwise, frame);
    }

    private RapidFlow While(RapidWhile w, RapidFrame frame)
    {
        while (Condition(w.Condition, frame))
        {
            Task.Tick();
            Step(w.Line);
            RapidFlow flow = ExecuteBlock(w.Body, frame);
            if (flow != RapidFlow.Next)
            {
                return flow;
            }
        }
        return RapidFlow.Next;
    }

    private RapidFlow Test(RapidTest t, RapidFrame frame)
    {
        object value = Evaluate(t.Value, frame);
        if (t.NumberCases is { } numbers && value is double number)
        {
            return numbers.TryGetValue(number == 0 ? 0.0 : number, out int k) ? ExecuteBlock(t.Cases[k].Body, frame)
                : t.Otherwise is null ? RapidFlow.Next : ExecuteBlock(t.Otherwise, frame);
        }
        foreach ((RapidExpr[] values, List<RapidStmt> body) in t.Cases)
        {
            foreach (RapidExpr v in values)
            {
                if (RapidValues.AreEqual(value, Evaluate(v, frame)))
                {
                    return ExecuteBlock(body, frame);
                }
            }
        }
        return t.Otherwise is null ? RapidFlow.Next : ExecuteBlock(t.Otherwise, frame);
    }

    private RapidFlow For(RapidFor f, RapidFrame frame)
    {
        double from = Number(f.From, frame), to = Number(f.To, frame);
        double step = f.Step is null ? (to >= from ? 1 : -1) : Number(f.Step, frame);
        if (step == 0)
        {
            throw new RapidRuntimeException(RapidErrorNumbers.ArgValErr, f.Line, "the STEP of a FOR loop is 0");
        }
        RapidCell cell = frame.Own(f.Slot, f.Variable, new RapidDataType(RapidTypes.Num), RapidStorage.Var, RapidBoxes.Num(from));
        for (double v = from; step > 0 ? v <= to : v >= to; v += step)
        {
            Task.Tick();
            Step(f.Line);
            cell.Value = RapidBoxes.Num(v);
            RapidFlow flow = ExecuteBlock(f.Body, frame);
            if (flow != RapidFlow.Next)
            {
                return flow;
            }
        }
        return RapidFlow.Next;
    }

    private RapidFlow Jump(RapidJump j, RapidFrame frame)
    {
        switch (j.Kind)
        {
            case RapidJumpKind.Label:
                return RapidFlow.Next;
            case RapidJumpKind.Goto:
                frame.GotoLabel = j.Label;
                return RapidFlow.Goto;
            case RapidJumpKind.Return:
                frame.ReturnValue = j.Value is null ? null : Evaluate(j.Value, frame);
                return RapidFlow.Return;
            case RapidJumpKind.Retry:
                return RapidFlow.Retry;
            case RapidJumpKind.TryNext:
                return RapidFlow.TryNext;
            case RapidJumpKind.Exit or RapidJumpKind.Stop:
                throw new RapidHaltException(j.Kind == RapidJumpKind.Exit, j.Line);
            default:
                if (j.Value is null)
                {
                    RapidRuntimeException handled = frame.Handling!;
                    handled.RaisedBy = frame;
                    throw handled;
                }
                double errno = (double)Evaluate(j.Value, frame);
                throw new RapidRuntimeException((int)errno, j.Line, $"error {RapidValues.FormatNumber(errno)} raised by the program and not handled");
        }
    }

    /// <summary>Calls a built-in or a routine of the program; returns a function's value.</summary>
    private object? Call(RapidCallTarget target, RapidArg[] args, RapidFrame? frame, int line)
    {
        if (target.Builtin is { } builtin)
        {
            return builtin.Run(new RapidCall(this, frame, args, target, line));
        }
        return Invoke(target.Routine!, args, target, frame, line);
    }

    /// <summary>
    /// True when <paramref name="arg"/> is (a part of) a local of <paramref name="caller"/> held in the caller's own cell. Given to an IN
    /// parameter that the routine never writes, while the routine takes nothing by reference and no argument calls a function, such a
    /// value needs no copy: the routine only reads it ("changing this variable will not change the corresponding argument", RAPID
    /// Overview, "Parameters"), and nothing can change it until the call returns (the caller waits, traps see no locals, and no
    /// reference to it is given to anyone).
    /// </summary>
    private static bool IsCallersOwn(RapidExpr arg, RapidFrame? caller)
    {
        return arg.Root is RapidName { Global: null, ReadsSignal: false } name && caller is not null && caller.HoldsOwn(name.Slot);
    }

    /// <summary>
    /// The sizes of a local array's dimensions. (A method of its own: a lambda over the frame in <see cref="Invoke"/> made the compiler
    /// allocate its closure at every call of every routine, array or not.)
    /// </summary>
    private int[] Dimensions(RapidDataDecl decl, RapidFrame frame)
    {
        var dims = new int[decl.Dimensions.Length];
        for (int d = 0; d < dims.Length; d++)
        {
            dims[d] = (int)Math.Clamp(Number(decl.Dimensions[d], frame), 0, int.MaxValue);
        }
        return dims;
    }

    private object? Invoke(RapidRoutine routine, RapidArg[] args, RapidCallTarget target, RapidFrame? caller, int line)
    {
        if (++_depth > Limits.MaxCallDepth)
        {
            _depth = 0;
            throw Budget(line, $"the routine calls are nested deeper than {Limits.MaxCallDepth} levels");
        }
        CheckStack(line);
        long elements = 0;
        try
        {
            RapidFrame frame = routine.TakeSpareFrame() ?? new RapidFrame(routine);
            RapidCell[] cells = frame.Cells;
            List<(RapidExpr Arg, RapidCell Cell)>? writeBack = null;
            for (int p = 0; p < routine.Parameters.Count; p++)
            {
                RapidParam param = routine.Parameters[p];
                RapidDataType type = routine.SlotTypes[p];
                int k = target.ArgumentOf[p];
                if (k < 0)
                {
                    frame.Own(p, param.Name, type, RapidStorage.Var, Absent);
                }
                else if (param.IsSwitch)
                {
                    frame.Own(p, param.Name, type, RapidStorage.Var, RapidBoxes.Bool(true));
                }
                else if (param.Mode != RapidParamMode.In && args[k].Value is RapidName name)
                {
                    cells[p] = name.Global ?? caller!.Cells[name.Slot];
                }
                else
                {
                    RapidExpr arg = args[k].Value!;
                    object value = Evaluate(arg, caller);
                    bool unshared = arg is RapidAggregate || (target.ArgumentsCallNoFunction && routine.TakesValuesOnly && !routine.WritesParameter[p] && IsCallersOwn(arg, caller));
                    RapidCell cell = frame.Own(p, param.Name, type, RapidStorage.Var, unshared ? value : RapidValues.Copy(value));
                    if (param.Mode != RapidParamMode.In)
                    {
                        (writeBack ??= []).Add((arg, cell));
                    }
                }
            }
            int slot = routine.Parameters.Count;
            foreach (RapidDataDecl decl in routine.Data)
            {
                RapidDataType type = routine.SlotTypes[slot];
                int[] dims = decl.Dimensions.Length == 0 ? [] : Dimensions(decl, frame);
                if (dims.Length > 0)
                {
                    long count = Limits.Elements(dims) ?? throw Budget(decl.Line, $"'{decl.Name}': {Limits.ArrayTooLarge(dims)}");
                    elements += count;
                    _localElements += count;
                    if (_localElements > Limits.MaxTotalElements)
                    {
                        throw Budget(decl.Line, $"the routines' local data hold more than {Limits.MaxTotalElements:N0} array elements (the twin's limit)");
                    }
                }
                object value = decl.Initial is not null ? RapidValues.Copy(Evaluate(decl.Initial, frame))
                    : (dims.Length == 0 && routine.Kind != RapidRoutineKind.Func ? frame.KeptRecord(slot, type) : null) ?? RapidValues.Default(type, dims);
                frame.Own(slot++, decl.Name, type, decl.Storage, value);
            }
            RapidFlow flow = routine.UndoHandler is null ? ExecuteBlock(routine.Body, frame) : ExecuteUndoable(routine, frame);
            if (flow == RapidFlow.Goto)
            {
                throw new RapidRuntimeException(0, line, $"the label '{frame.GotoLabel}' cannot be reached from its GOTO");
            }
            if (writeBack is not null)
            {
                foreach ((RapidExpr arg, RapidCell cell) in writeBack)
                {
                    Store(arg, caller, cell.Value);
                }
            }
            object? returned = frame.ReturnValue;
            if (routine.Kind == RapidRoutineKind.Func && returned is null)
            {
                throw new RapidRuntimeException(0, line, $"the function '{routine.Name}' ended without RETURN");
            }
            frame.Reuse();
            routine.KeepSpareFrame(frame); // only after a normal return: a frame an error left may still be named by that error
            return returned;
        }
        finally
        {
            _depth--;
            _localElements -= elements;
        }
    }
}
