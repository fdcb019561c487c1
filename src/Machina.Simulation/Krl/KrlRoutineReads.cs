namespace Machina.Simulation.Krl;

/// <summary>
/// What a routine does with its IN parameters, found once from its statements: an IN structure parameter that the routine only
/// reads (its components, or the whole value copied, compared, moved to or handed to another routine's IN parameter) can hold
/// the caller's own structure instead of a copy, when nothing can change that structure while the routine runs. The driver's
/// <c>machina_check_target(id, target)</c> copied its FRAME at every action (112 bytes).
/// </summary>
/// <remarks>
/// A parameter does not qualify when anything could write it or keep it: an assignment, an OUT argument or a FOR counter rooted
/// at it, the whole value handed to a built-in (which may keep what it is given), or an INTERRUPT DECL or TRIGGER in the routine
/// (which evaluate in its frame after later statements). The caller's side (<see cref="KrlCall.SharedArguments"/>) asks that the
/// argument be a local of the caller, a routine without INTERRUPT DECL and TRIGGER (nothing else can write a local while a
/// routine it called runs).
/// </remarks>
internal sealed class KrlRoutineReads
{
    private KrlRoutineReads(int readOnly, bool keepsFrame, List<KrlCall> calls)
    {
        ReadOnlyParameters = readOnly;
        KeepsFrame = keepsFrame;
        _calls = calls;
    }

    /// <summary>The calls of routines of the program in the body, until <see cref="MarkCalls"/> marked them.</summary>
    private List<KrlCall>? _calls;

    /// <summary>Bit i set: IN parameter i is only read (see the class).</summary>
    public int ReadOnlyParameters { get; }

    /// <summary>True when the routine has an INTERRUPT DECL or a TRIGGER (something may be evaluated in its frame later).</summary>
    public bool KeepsFrame { get; }

    /// <summary>The parameters' count beyond which none qualifies (the bits of an <see cref="int"/>).</summary>
    private const int MaxParameters = 31;

    /// <summary>
    /// Marks the routine's calls whose arguments the called routines' parameters may hold as they are (each called routine's
    /// <see cref="ReadOnlyParameters"/>, found from its own statements only: no walk waits for another, recursion included).
    /// </summary>
    public void MarkCalls()
    {
        if (_calls is not { } calls)
        {
            return;
        }
        foreach (KrlCall call in calls)
        {
            call.SharedArguments = KeepsFrame ? 0 : SharedOf(call);
        }
        _calls = null;
    }

    /// <summary>Finds what <paramref name="routine"/> does with its parameters (its calls are marked by <see cref="MarkCalls"/>).</summary>
    public static KrlRoutineReads Of(KrlRoutine routine)
    {
        var walk = new Walk(Math.Min(routine.Parameters.Count, MaxParameters));
        walk.Statements(routine.Body);
        int readOnly = 0;
        if (!walk.KeepsFrame)
        {
            for (int i = 0; i < walk.Written.Length; i++)
            {
                if (!walk.Written[i] && !routine.Parameters[i].IsOut && !routine.Parameters[i].IsArray)
                {
                    readOnly |= 1 << i;
                }
            }
        }
        return new KrlRoutineReads(readOnly, walk.KeepsFrame, walk.Calls);
    }

    /// <summary>The arguments of <paramref name="call"/> (a call of a routine of the program) that are locals of the caller and parameters the routine only reads.</summary>
    private static int SharedOf(KrlCall call)
    {
        if (call.Routine is not { } callee)
        {
            return 0;
        }
        int readOnly = callee.Reads.ReadOnlyParameters, shared = 0;
        KrlExpr[] given = call.Each;
        for (int i = 0; i < given.Length && i < MaxParameters; i++)
        {
            if ((readOnly & (1 << i)) != 0 && given[i] is KrlName { Slot: >= 0 })
            {
                shared |= 1 << i;
            }
        }
        return shared;
    }

    /// <summary>One pass over a routine's statements.</summary>
    private sealed class Walk(int parameters)
    {
        /// <summary>Parameter i written (or kept) somewhere.</summary>
        public bool[] Written { get; } = new bool[parameters];

        /// <summary>An INTERRUPT DECL or TRIGGER seen.</summary>
        public bool KeepsFrame { get; private set; }

        /// <summary>The calls of routines of the program in the body.</summary>
        public List<KrlCall> Calls { get; } = [];

        public void Statements(List<KrlStmt>? body)
        {
            if (body is null)
            {
                return;
            }
            foreach (KrlStmt statement in body)
            {
                Statement(statement);
            }
        }

        private void Statement(KrlStmt statement)
        {
            switch (statement)
            {
                case KrlAssign assign:
                    Target(assign.Target);
                    Read(assign.Value);
                    return;
                case KrlCallStmt call:
                    Read(call.Call);
                    return;
                case KrlIf branch:
                    Read(branch.Condition);
                    Statements(branch.Then);
                    Statements(branch.Else);
                    return;
                case KrlLoop loop:
                    if (loop.Condition is not null)
                    {
                        Read(loop.Condition);
                    }
                    Statements(loop.Body);
                    return;
                case KrlFor loop:
                    Target(loop.Counter);
                    Read(loop.From);
                    Read(loop.To);
                    if (loop.Step is not null)
                    {
                        Read(loop.Step);
                    }
                    Statements(loop.Body);
                    return;
                case KrlSwitch choice:
                    Read(choice.Selector);
                    foreach ((List<KrlExpr> values, List<KrlStmt> body) in choice.Cases)
                    {
                        values.ForEach(Read);
                        Statements(body);
                    }
                    Statements(choice.Default);
                    return;
                case KrlWait wait:
                    Read(wait.Value);
                    return;
                case KrlMotion motion:
                    Read(motion.Target);
                    if (motion.Auxiliary is not null)
                    {
                        Read(motion.Auxiliary);
                    }
                    return;
                case KrlJump jump:
                    if (jump.Value is not null)
                    {
                        Read(jump.Value);
                    }
                    return;
                case KrlGoto or KrlLabel or KrlInterruptSwitch:
                    return;
                default:
                    // INTERRUPT DECL, TRIGGER, or a statement this walk does not know: nothing qualifies.
                    KeepsFrame = true;
                    return;
            }
        }

        /// <summary>An expression read as a value: a parameter may appear whole or as a component.</summary>
        private void Read(KrlExpr expr)
        {
            switch (expr)
            {
                case KrlName or KrlLiteral or KrlOmitted:
                    return;
                case KrlMember member:
                    Read(member.Target);
                    return;
                case KrlIndex index:
                    Read(index.Target);
                    Indices(index);
                    return;
                case KrlUnary unary:
                    Read(unary.Operand);
                    return;
                case KrlBinary binary:
                    Read(binary.Left);
                    Read(binary.Right);
                    return;
                case KrlAggregate aggregate:
                    foreach ((string _, KrlExpr value) in aggregate.Fields)
                    {
                        Read(value);
                    }
                    return;
                case KrlCall call:
                    Call(call);
                    return;
                default:
                    KeepsFrame = true;
                    return;
            }
        }

        private void Call(KrlCall call)
        {
            KrlExpr[] given = call.Each;
            if (call.Routine is { } routine)
            {
                Calls.Add(call);
            }
            else if (call.Builtin is null)
            {
                KeepsFrame = true;
                return;
            }
            for (int i = 0; i < given.Length; i++)
            {
                bool isOut = call.Routine is { } r ? i < r.Parameters.Count && r.Parameters[i].IsOut : i < call.Builtin!.Parameters.Length && call.Builtin.Parameters[i].IsOut;
                if (isOut)
                {
                    Target(given[i]);
                }
                else if (call.Routine is null && given[i] is KrlName)
                {
                    // The whole value handed to a built-in, which may keep it.
                    Target(given[i]);
                }
                else
                {
                    Read(given[i]);
                }
            }
        }

        /// <summary>The indices of an element or row, read.</summary>
        private void Indices(KrlIndex index)
        {
            foreach (KrlExpr? i in index.Each)
            {
                if (i is not null)
                {
                    Read(i);
                }
            }
        }

        /// <summary>A place written: the parameter it is rooted at is written; its indices are read.</summary>
        private void Target(KrlExpr expr)
        {
            switch (expr)
            {
                case KrlName { Slot: >= 0 } name:
                    if (name.Slot < Written.Length)
                    {
                        Written[name.Slot] = true;
                    }
                    return;
                case KrlMember member:
                    Target(member.Target);
                    return;
                case KrlIndex index:
                    Target(index.Target);
                    Indices(index);
                    return;
                case KrlName or KrlOmitted:
                    return;
                default:
                    Read(expr);
                    return;
            }
        }
    }
}
