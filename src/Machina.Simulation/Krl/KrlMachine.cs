using System.Runtime.CompilerServices;
using Machina.Simulation.Twin;

namespace Machina.Simulation.Krl;

/// <summary>
/// The robot interpreter of a KRL twin: runs a routine's statements one line after another, with frames for locals, the
/// interrupts the program declared, and motions and waits handed to the controller.
/// </summary>
internal sealed partial class KrlMachine(KrlTwinController controller, CancellationToken cancellation)
{
    private enum Flow
    {
        Next,
        Exit,
        Return,
        Goto,
    }

    private readonly Dictionary<int, KrlInterruptState> _interrupts = [];
    private int _interruptsOn;

    /// <summary>The declared interrupts, highest priority (lowest number) first.</summary>
    private KrlInterruptState[] _interruptOrder = [];
    private long _writes;

    /// <summary>True when a declared interrupt's condition reads more than data list and system variables (a call, a local).</summary>
    private bool _watchesAll;

    /// <summary>True when a declared interrupt's condition reads a variable the controller computes when read ($TIMER, $POS_ACT).</summary>
    private bool _watchesComputed;

    /// <summary>True once a declared interrupt's condition reads something whose change wakes no one (<see cref="KrlInterruptDecl.Woken"/>).</summary>
    private bool _interruptsLookAtTime;

    /// <summary>The controller's count of writes of watched variables when the conditions were last looked at.</summary>
    private long _checkedWatchedWrites;
    private long _checkedWrites = -1;
    private long _checkedInputs = -1;
    private bool _inInterrupt;
    private object[]? _interruptFrame;
    private object? _returned;
    private string? _gotoLabel;
    private KrlRoutine _routine = null!;
    private int _depth;
    private long _steps;
    private int _stackChecks;

    /// <summary>The array elements of the routines' local data now (bounded by <see cref="TwinLimits.MaxTotalElements"/>).</summary>
    private long _localElements;

    /// <summary>The interpreter's budgets.</summary>
    public TwinLimits Limits { get; } = controller.Options.Limits;

    /// <summary>
    /// Throws the interpreter's error when the running thread has too little stack left for one more level. The runtime is asked
    /// at every 8th call (<see cref="TwinLimits.StackCheckEvery"/>).
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private void CheckStack()
    {
        if ((++_stackChecks & (TwinLimits.StackCheckEvery - 1)) == 0)
        {
            AskForStack();
        }
    }

    private static void AskForStack()
    {
        if (TwinLimits.StackLow)
        {
            throw new KrlRuntimeException("stack overflow: the subprogram calls and expressions are nested too deeply");
        }
    }

    /// <summary>The controller.</summary>
    public KrlTwinController Controller { get; } = controller;

    /// <summary>Stops waits and motions when cancelled.</summary>
    public CancellationToken Cancellation { get; } = cancellation;

    /// <summary>
    /// Called after each turn of a LOOP … ENDLOOP (null: none): the submit interpreter runs one turn of sps.sub's endless loop per
    /// interpreter cycle instead of holding a processor.
    /// </summary>
    public Action<CancellationToken>? LoopTurnWait { get; init; }

    /// <summary>The robot interpreter's held sends, counted per statement (<see cref="Twin.TwinHeldSends.StatementBound"/>); null elsewhere.</summary>
    public Twin.TwinHeldSends? Sends { get; init; }

    /// <summary>The line being run.</summary>
    public int Line { get; private set; }

    /// <summary>
    /// Where the line is kept for the traces of what this interpreter writes, set before each statement: the controller's robot
    /// line (<see cref="KrlTwinController.Line"/>) unless given a submit interpreter's own.
    /// </summary>
    public KrlRunningLine TracedLine { get; init; } = controller.RobotLine;

    /// <summary>The file being run.</summary>
    public string File => _routine?.File ?? "";

    /// <summary>Runs <paramref name="routine"/> (a subprogram without parameters) to its END.</summary>
    public void Run(KrlRoutine routine) => Invoke(routine, []);

    /// <summary>Runs a routine with its arguments (values for IN, places for OUT); returns a function's value.</summary>
    /// <param name="routine">The routine.</param>
    /// <param name="arguments">Its arguments.</param>
    /// <param name="shared">Bit i set: argument i is a structure the routine's IN parameter holds as it is (<see cref="KrlCall.SharedArguments"/>).</param>
    public object? Invoke(KrlRoutine routine, object[] arguments, int shared = 0)
    {
        if (_depth >= Limits.MaxCallDepth)
        {
            throw new KrlRuntimeException($"the subprogram calls are nested deeper than {Limits.MaxCallDepth} levels ({routine.Name})");
        }
        CheckStack();
        long elements = routine.Frame.Elements;
        if (_localElements + elements > Limits.MaxTotalElements)
        {
            throw new KrlRuntimeException($"the subprograms' local data hold more than {Limits.MaxTotalElements:N0} array elements (the twin's limit)");
        }
        _depth++;
        _localElements += elements;
        try
        {
            return InvokeWithin(routine, arguments, shared);
        }
        finally
        {
            _depth--;
            _localElements -= elements;
        }
    }

    private object? InvokeWithin(KrlRoutine routine, object[] arguments, int shared)
    {
        routine.Reads.MarkCalls(); // its calls' shared arguments are marked before its first statement runs
        KrlType[] types = routine.Frame.Types;
        object[] frame = TakeFrame(types.Length);
        long keeps = _frameKeeps;
        for (int i = 0; i < frame.Length; i++)
        {
            KrlType type = types[i];
            if (i < arguments.Length && arguments[i] is not null)
            {
                object value = arguments[i] is KrlPlace place ? place.Get() : arguments[i];
                if ((shared & (1 << i)) != 0 && value is KrlStructValue { HoldsNumbers: true } structure && structure.Type == type)
                {
                    frame[i] = structure; // an IN parameter only read, the caller's local that nothing changes meanwhile: no copy
                    continue;
                }
                frame[i] = type.Kind == KrlKind.Array && type.Sizes.Any(s => s == 0)
                    ? KrlConvert.To(value is KrlArrayValue a ? a.Type : KrlType.Array(KrlType.Char, Math.Max(1, ((string)value).Length)), value, null)
                    : KrlConvert.To(type, value, null);
            }
            else if (i < routine.Parameters.Count || type.Kind is not (KrlKind.Struct or KrlKind.Array))
            {
                frame[i] = KrlValues.Default(type);
            }
            // A structure or array local is made at its first use (LocalValue): the driver's machina_run declares an EKI_STATUS, two
            // FRAMEs and an AXIS, and a LIN uses one FRAME; ret only ever takes what the EKI_ functions return.
        }
        KrlRoutine caller = _routine;
        int callerLine = Line;
        _routine = routine;
        try
        {
            Flow flow = Block(routine.Body, frame);
            if (flow == Flow.Goto)
            {
                throw new KrlRuntimeException($"GOTO {_gotoLabel}: a jump into a control structure (IF, loop, SWITCH) from outside it is not allowed");
            }
            if (routine.ReturnType is not null && flow != Flow.Return)
            {
                throw new KrlRuntimeException($"the function {routine.Name} ended without RETURN");
            }
            for (int i = 0; i < arguments.Length; i++)
            {
                if (arguments[i] is KrlPlace place && routine.Parameters[i].IsOut)
                {
                    place.Set(frame[i]);
                }
            }
            object? result = _returned;
            _returned = null;
            return result;
        }
        catch (KrlRuntimeException ex) when (ex.File is null)
        {
            ex.File = routine.File;
            ex.Line = Line;
            throw;
        }
        finally
        {
            _routine = caller;
            Line = callerLine;
            if (_frameKeeps == keeps)
            {
                GiveBackFrame(frame);
            }
        }
    }

    private Flow Block(List<KrlStmt> body, object[] frame)
    {
        for (int i = 0; i < body.Count; i++)
        {
            KrlStmt statement = body[i];
            Line = statement.Line;
            Step();
            Sends?.Statement();
            TracedLine.Value = statement.Line;
            if (_interruptsOn > 0 && !_inInterrupt
                && (_writes != _checkedWrites || Controller.InputsVersion != _checkedInputs || (Controller.TimersCounting && ConditionsMayHaveChanged())))
            {
                // An interrupt's condition reads global and system variables only: it can only change after such a write or an input.
                _checkedWrites = _writes;
                _checkedInputs = Controller.InputsVersion;
                CheckInterrupts();
            }
            Flow flow = Statement(statement, frame);
            if (flow != Flow.Next)
            {
                if (flow == Flow.Goto && KrlLabel.IndexIn(body, _gotoLabel!) is >= 0 and var label)
                {
                    // The label is in this block: go on after it (a GOTO out of nested blocks ends them on the way here).
                    _gotoLabel = null;
                    Cancellation.ThrowIfCancellationRequested();
                    i = label;
                    continue;
                }
                return flow;
            }
        }
        return Flow.Next;
    }

    private Flow Statement(KrlStmt statement, object[] frame)
    {
        switch (statement)
        {
            case KrlAssign assign:
            {
                if (AssignRealComponent(assign, frame))
                {
                    return Flow.Next;
                }
                object value = Eval(assign.Value, frame);
                if (assign.Value is KrlCall { Builtin.ReturnsFresh: true } && assign.Target is KrlName { Slot: >= 0 } local
                    && value is KrlStructValue made && made.Type == local.Type)
                {
                    // A structure the built-in made for this call (ret = EKI_…): the local takes it as it is, the copy would be the same.
                    frame[local.Slot] = made;
                    return Flow.Next;
                }
                Assign(assign, value, frame);
                return Flow.Next;
            }
            case KrlCallStmt call:
                try
                {
                    Call(call.Call, frame);
                }
                catch (KrlResumeSignal resume) when (ReferenceEquals(resume.DeclaringFrame, frame))
                {
                    // RESUME of an interrupt this routine declared: the call it ran is abandoned and the program goes on after it.
                }
                if (!WritesNothingWatched(call.Call))
                {
                    _writes++;
                }
                return Flow.Next;
            case KrlIf branch:
                return Block(BoolOf(branch.Condition, frame) ? branch.Then : branch.Else, frame);
            case KrlLoop loop:
                return Loop(loop, frame);
            case KrlFor loop:
                return For(loop, frame);
            case KrlSwitch choice:
                return Block(Select(choice, frame), frame);
            case KrlWait wait:
                Wait(wait, frame);
                return Flow.Next;
            case KrlTrigger trigger:
                KeepFrame();
                _triggers.Add((trigger, frame));
                return Flow.Next;
            case KrlMotion motion:
                RunTriggers(atEnd: false);
                Controller.MotionRuns(starts: true);
                try
                {
                    Controller.Move(motion.Kind, GivenComponents(Eval(motion.Target, frame)), motion.Auxiliary is null ? null : Eval(motion.Auxiliary, frame),
                        motion.Approximation, motion.Line, Cancellation);
                }
                finally
                {
                    DisarmTimerWake();
                    Controller.MotionRuns(starts: false);
                }
                RunTriggers(atEnd: true);
                return Flow.Next;
            case KrlJump jump:
                return Jump(jump, frame);
            case KrlGoto jump:
                _gotoLabel = jump.Label;
                return Flow.Goto;
            case KrlLabel:
                return Flow.Next;
            case KrlInterruptDecl declaration:
                KeepFrame();
                if (_interrupts.TryGetValue(declaration.Priority, out KrlInterruptState? old))
                {
                    if (old.On)
                    {
                        _interruptsOn--;
                    }
                    old.Declaration = declaration;
                    old.Frame = frame;
                    old.On = false;
                    old.Last = false;
                }
                else
                {
                    _interrupts[declaration.Priority] = new KrlInterruptState(declaration, frame);
                    _interruptOrder = [.. _interrupts.OrderBy(e => e.Key).Select(e => e.Value)];
                }
                Watch(declaration.Condition);
                _interruptsLookAtTime |= !declaration.Woken;
                return Flow.Next;
            case KrlInterruptSwitch change:
                SwitchInterrupts(change);
                return Flow.Next;
            default:
                throw new KrlRuntimeException("a statement the twin cannot run");
        }
    }

    /// <summary>
    /// A motion's target as the components it was given: a POS or E6POS whose status S or turn T was never given (assigned an
    /// aggregate without them, e.g. <c>P = {X 0, Y 0, Z 0, A 0, B 0, C 0}</c>) leaves them out, so that a PTP takes the solution
    /// nearest the current axes instead of S 'B000' and T 'B000000' (KUKA: without S and T the controller keeps the current status
    /// and takes the shortest way).
    /// </summary>
    private static object GivenComponents(object target)
    {
        if (target is not KrlStructValue { Unset: not 0 } position)
        {
            return target;
        }
        int[] given = [.. Enumerable.Range(0, position.Values.Length).Where(position.IsGiven)];
        return new KrlPartialValue(position.Type, given, [.. given.Select(i => position.Values[i])]);
    }

    /// <summary>Counts one statement or loop turn against the step budget.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private void Step()
    {
        if (++_steps > Limits.MaxSteps && Limits.MaxSteps > 0)
        {
            StepsSpent();
        }
    }

    /// <summary>The step budget's error, out of <see cref="Step"/> (its message made a call of every statement's count).</summary>
    private void StepsSpent() =>
        throw new KrlRuntimeException($"the program ran more than {Limits.MaxSteps:N0} statements and loop turns (the verification's step budget): an endless loop?");

    private Flow Loop(KrlLoop loop, object[] frame)
    {
        while (true)
        {
            Cancellation.ThrowIfCancellationRequested();
            Step();
            if (loop.Kind == KrlLoopKind.While && !BoolOf(loop.Condition!, frame))
            {
                return Flow.Next;
            }
            Flow flow = Block(loop.Body, frame);
            if (flow == Flow.Exit)
            {
                return Flow.Next;
            }
            if (flow != Flow.Next)
            {
                return flow;
            }
            Line = loop.Line;
            if (loop.Kind == KrlLoopKind.Repeat && BoolOf(loop.Condition!, frame))
            {
                return Flow.Next;
            }
            if (loop.Kind == KrlLoopKind.Loop)
            {
                LoopTurnWait?.Invoke(Cancellation);
            }
        }
    }

    private Flow For(KrlFor loop, object[] frame)
    {
        KrlPlace counter = Place(loop.Counter, frame);
        int from = IntOf(loop.From, frame);
        int to = IntOf(loop.To, frame);
        int step = loop.Step is null ? 1 : IntOf(loop.Step, frame);
        if (step == 0)
        {
            throw new KrlRuntimeException("FOR with STEP 0 never ends");
        }
        // A long counter: a loop up to the largest INT ends instead of wrapping round.
        for (long i = from; step > 0 ? i <= to : i >= to; i += step)
        {
            Cancellation.ThrowIfCancellationRequested();
            Step();
            counter.Set(KrlValues.Box((int)i));
            Flow flow = Block(loop.Body, frame);
            if (flow == Flow.Exit)
            {
                return Flow.Next;
            }
            if (flow != Flow.Next)
            {
                return flow;
            }
        }
        return Flow.Next;
    }

    private List<KrlStmt> Select(KrlSwitch choice, object[] frame)
    {
        object selector = Eval(choice.Selector, frame);
        foreach ((List<KrlExpr> values, List<KrlStmt> body) in choice.Cases)
        {
            foreach (KrlExpr value in values)
            {
                if (Equal(selector, Eval(value, frame)))
                {
                    return body;
                }
            }
        }
        return choice.Default ?? [];
    }

    private void Wait(KrlWait wait, object[] frame)
    {
        Controller.EndAdvanceRun(Cancellation);
        if (!wait.ForCondition)
        {
            double seconds = RealOf(wait.Value, frame);
            Controller.WaitSeconds(seconds, wait.Line, Cancellation);
            return;
        }
        if (BoolOf(wait.Value, frame))
        {
            return;
        }
        KrlWaitWake wake = Controller.WaitWake;
        wake.Waits();
        try
        {
            while (true)
            {
                // The change count before the look that decides to sleep: a change after the look ends the sleep at once.
                long version = Controller.InputsVersion;
                if (BoolOf(wait.Value, frame))
                {
                    return;
                }
                // Looks again every interpreter cycle while a timer runs only when the condition, or an interrupt that is
                // served while it waits, reads something whose change wakes no one (a timer, a function, a computed variable).
                bool serves = _interruptsOn > 0 && !_inInterrupt;
                Controller.WaitForInputs(version, !wait.Woken || (serves && _interruptsLookAtTime), Cancellation);
                if (serves)
                {
                    CheckInterrupts();
                }
            }
        }
        finally
        {
            wake.Ends();
        }
    }

    private Flow Jump(KrlJump jump, object[] frame)
    {
        switch (jump.Keyword)
        {
            case "EXIT":
                return Flow.Exit;
            case "RETURN":
                _returned = jump.Value is null ? null : KrlConvert.To(_routine.ReturnType!, Eval(jump.Value, frame), null);
                return Flow.Return;
            case "HALT":
                throw new KrlHaltException(jump.Line, _routine.File);
            case "BRAKE":
            case "BRAKE F":
                // The interrupted motion stops where the arm is (at once: the braking ramp is not modelled) and goes on when the routine returns.
                if (!_inInterrupt)
                {
                    throw new KrlRuntimeException($"{jump.Keyword} is only allowed in an interrupt routine");
                }
                Controller.Arm.Brake();
                return Flow.Next;
            case "RESUME":
                throw _inInterrupt
                    ? new KrlResumeSignal(_interruptFrame!, jump.Line, _routine.File)
                    : new KrlRuntimeException("RESUME is only allowed in an interrupt routine");
            default:
                return Flow.Next;
        }
    }

    private void SwitchInterrupts(KrlInterruptSwitch change)
    {
        foreach (int priority in _interrupts.Keys.ToList())
        {
            if (change.Priority is { } p && p != priority)
            {
                continue;
            }
            KrlInterruptState entry = _interrupts[priority];
            bool on = change.Action is "ON" or "ENABLE";
            if (on != entry.On)
            {
                _interruptsOn += on ? 1 : -1;
            }
            bool last = on && BoolOf(entry.Declaration.Condition, entry.Frame);
            entry.On = on;
            entry.Last = last;
        }
        if (change.Priority is { } missing && !_interrupts.ContainsKey(missing))
        {
            throw new KrlRuntimeException($"interrupt {missing} is not declared");
        }
    }

    /// <summary>
    /// Serves the interrupts while a motion is under way (the arm calls it as each part of the motion starts, and each time the
    /// motion is woken: by a flag, input or channel, or by a running timer reaching 0, see <see cref="ArmTimerWake"/> and
    /// <see cref="ProgramTimeWake"/>; on this interpreter's thread): the motion goes on while an interrupt routine runs, as on the
    /// controller, until a BRAKE in it stops the arm; a braked motion goes on when the routine returns, and RESUME leaves the arm
    /// where it stands.
    /// </summary>
    public void ServeInterrupts()
    {
        if (_interruptsOn > 0 && !_inInterrupt)
        {
            _checkedWrites = _writes;
            _checkedInputs = Controller.InputsVersion;
            CheckInterrupts();
            ArmTimerWake(); // the next timer to reach 0 wakes the motion again (a routine may have set its timer back)
        }
    }

    /// <summary>
    /// Marks the variables <paramref name="condition"/> reads (<see cref="KrlCell.Watched"/>), so that a write of an element of
    /// any other variable does not make the interpreter look at the conditions again; a condition that calls a function or reads a
    /// local is looked at after every write, as before.
    /// </summary>
    private void Watch(KrlExpr condition)
    {
        switch (condition)
        {
            case KrlLiteral:
                return;
            case KrlName { Cell: { } cell }:
                cell.Watch(Controller.WatchedWrites);
                _watchesComputed |= cell.Read is not null && cell.Signals is null;
                return;
            case KrlIndex index:
                Watch(index.Target);
                foreach (KrlExpr? i in index.Indices)
                {
                    if (i is not null)
                    {
                        Watch(i);
                    }
                }
                return;
            case KrlMember member:
                Watch(member.Target);
                return;
            case KrlUnary unary:
                Watch(unary.Operand);
                return;
            case KrlBinary binary:
                Watch(binary.Left);
                Watch(binary.Right);
                return;
            default:
                _watchesAll = true;
                return;
        }
    }

    /// <summary>
    /// While a timer counts (a submit interpreter's, e.g. the KUKA monitor's period) the conditions were looked at before every
    /// statement, as time passes; they can only have changed when one reads a computed variable or a function, or when another
    /// interpreter wrote a variable one reads. Before, the driver's three conditions were evaluated at every statement, all stream long.
    /// </summary>
    private bool ConditionsMayHaveChanged()
    {
        if (_watchesAll || _watchesComputed)
        {
            return true;
        }
        // One count for every watched variable of the controller (any interpreter's conditions): one read per statement.
        long writes = Controller.WatchedWrites.Count;
        if (writes == _checkedWatchedWrites)
        {
            return false;
        }
        _checkedWatchedWrites = writes;
        return true;
    }

    /// <summary>Runs the handler of each switched-on interrupt whose condition has just become TRUE (edge), highest priority first.</summary>
    private void CheckInterrupts()
    {
        foreach (KrlInterruptState entry in _interruptOrder)
        {
            if (!entry.On)
            {
                continue;
            }
            KrlInterruptDecl declaration = entry.Declaration;
            object[] frame = entry.Frame;
            bool now = BoolOf(declaration.Condition, frame);
            bool last = entry.Last;
            entry.Last = now;
            if (now && !last)
            {
                _inInterrupt = true;
                _interruptFrame = frame;
                int line = Line;
                try
                {
                    Call(declaration.Handler, frame);
                    // The condition as the routine left it (a timer set back, a flag reset): the controller's next cycle sees it so,
                    // however long the twin's thread waits before its next look, and its next rising edge is not lost.
                    if (entry.On && ReferenceEquals(entry.Declaration, declaration))
                    {
                        entry.Last = BoolOf(declaration.Condition, entry.Frame);
                    }
                }
                finally
                {
                    _inInterrupt = false;
                    _interruptFrame = null;
                    Line = line;
                }
            }
        }
    }
}
