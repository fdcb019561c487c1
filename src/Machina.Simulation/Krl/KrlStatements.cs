namespace Machina.Simulation.Krl;

/// <summary>A statement of a KRL routine, at its line.</summary>
internal abstract class KrlStmt(int line)
{
    /// <summary>The 1-based line.</summary>
    public int Line { get; } = line;
}

/// <summary><c>target = value</c>.</summary>
internal sealed class KrlAssign(int line, KrlExpr target, KrlExpr value) : KrlStmt(line)
{
    /// <summary>The variable, element or component assigned.</summary>
    public KrlExpr Target { get; } = target;

    /// <summary>The value.</summary>
    public KrlExpr Value { get; } = value;

    private KrlStore _store;

    /// <summary>How the interpreter stores into <see cref="Target"/> (found at the first run, when the program is bound).</summary>
    public KrlStore Store => _store != KrlStore.Unknown ? _store : _store = StoreOf(Target);

    private static KrlStore StoreOf(KrlExpr target) => target switch
    {
        KrlName { Slot: >= 0 } => KrlStore.Local,
        KrlIndex { Target: KrlName { Slot: >= 0 } or KrlName { Cell.Written: null } } index when index.Each.Length > 0 && index.Each[^1] is not null => KrlStore.Element,
        KrlMember { Target: KrlName { Slot: >= 0 } } => KrlStore.LocalMember,
        KrlName { Cell.Signals: null } => KrlStore.Cell,
        _ => KrlStore.Place,
    };
}

/// <summary>The kinds of store of <see cref="KrlAssign"/>.</summary>
internal enum KrlStore : byte
{
    /// <summary>Not found yet.</summary>
    Unknown,

    /// <summary>A local variable or parameter.</summary>
    Local,

    /// <summary>An element of an array local, or of an array variable told of no write (<see cref="KrlCell.Written"/>).</summary>
    Element,

    /// <summary>A component of a local structure.</summary>
    LocalMember,

    /// <summary>A variable of a data list or a system variable (not an IO array).</summary>
    Cell,

    /// <summary>Through its place (<see cref="KrlPlace"/>).</summary>
    Place,
}

/// <summary>A routine call as a statement.</summary>
internal sealed class KrlCallStmt(int line, KrlCall call) : KrlStmt(line)
{
    /// <summary>The call.</summary>
    public KrlCall Call { get; } = call;
}

/// <summary>IF … THEN … ELSE … ENDIF.</summary>
internal sealed class KrlIf(int line, KrlExpr condition, List<KrlStmt> then, List<KrlStmt> otherwise) : KrlStmt(line)
{
    /// <summary>The condition.</summary>
    public KrlExpr Condition { get; } = condition;

    /// <summary>The THEN branch.</summary>
    public List<KrlStmt> Then { get; } = then;

    /// <summary>The ELSE branch (empty without ELSE).</summary>
    public List<KrlStmt> Else { get; } = otherwise;
}

/// <summary>A loop: WHILE (test first), REPEAT … UNTIL (test last) or LOOP (endless, left with EXIT).</summary>
internal sealed class KrlLoop(int line, KrlLoopKind kind, KrlExpr? condition, List<KrlStmt> body) : KrlStmt(line)
{
    /// <summary>Which loop.</summary>
    public KrlLoopKind Kind { get; } = kind;

    /// <summary>WHILE's condition to go on, REPEAT's condition to stop (null for LOOP).</summary>
    public KrlExpr? Condition { get; } = condition;

    /// <summary>The body.</summary>
    public List<KrlStmt> Body { get; } = body;
}

/// <summary>The kinds of conditional loops.</summary>
internal enum KrlLoopKind
{
    /// <summary>WHILE … ENDWHILE.</summary>
    While,

    /// <summary>REPEAT … UNTIL.</summary>
    Repeat,

    /// <summary>LOOP … ENDLOOP.</summary>
    Loop,
}

/// <summary>FOR counter = from TO to STEP step … ENDFOR (the counter is an INT).</summary>
internal sealed class KrlFor(int line, KrlName counter, KrlExpr from, KrlExpr to, KrlExpr? step, List<KrlStmt> body) : KrlStmt(line)
{
    /// <summary>The counter variable.</summary>
    public KrlName Counter { get; } = counter;

    /// <summary>The first value.</summary>
    public KrlExpr From { get; } = from;

    /// <summary>The last value.</summary>
    public KrlExpr To { get; } = to;

    /// <summary>The increment (1 when left out).</summary>
    public KrlExpr? Step { get; } = step;

    /// <summary>The body.</summary>
    public List<KrlStmt> Body { get; } = body;
}

/// <summary>SWITCH … CASE … DEFAULT … ENDSWITCH.</summary>
internal sealed class KrlSwitch(int line, KrlExpr selector, List<(List<KrlExpr> Values, List<KrlStmt> Body)> cases, List<KrlStmt>? otherwise) : KrlStmt(line)
{
    /// <summary>The value selected on.</summary>
    public KrlExpr Selector { get; } = selector;

    /// <summary>Each CASE: its values and body.</summary>
    public List<(List<KrlExpr> Values, List<KrlStmt> Body)> Cases { get; } = cases;

    /// <summary>The DEFAULT body (null without DEFAULT).</summary>
    public List<KrlStmt>? Default { get; } = otherwise;
}

/// <summary>WAIT SEC seconds, or WAIT FOR condition.</summary>
internal sealed class KrlWait(int line, bool forCondition, KrlExpr value) : KrlStmt(line)
{
    /// <summary>True for WAIT FOR, false for WAIT SEC.</summary>
    public bool ForCondition { get; } = forCondition;

    /// <summary>The seconds or the condition.</summary>
    public KrlExpr Value { get; } = value;

    /// <summary>
    /// For WAIT FOR, true when every variable the condition reads is woken on change (set when the program is loaded, see
    /// <see cref="KrlWaitWake"/>): the wait then sleeps until something changes instead of looking again every interpreter cycle.
    /// </summary>
    public bool Woken { get; set; }
}

/// <summary>A motion: PTP, LIN or CIRC to a target, with an approximation (C_PTP, C_DIS, C_ORI, C_VEL) or none.</summary>
internal sealed class KrlMotion(int line, string kind, KrlExpr target, KrlExpr? auxiliary, string? approximation) : KrlStmt(line)
{
    /// <summary>PTP, LIN or CIRC.</summary>
    public string Kind { get; } = kind;

    /// <summary>The end point.</summary>
    public KrlExpr Target { get; } = target;

    /// <summary>CIRC's auxiliary point (null otherwise).</summary>
    public KrlExpr? Auxiliary { get; } = auxiliary;

    /// <summary>The approximation keyword, or null for an exact stop.</summary>
    public string? Approximation { get; } = approximation;
}

/// <summary>A statement without operands: EXIT, HALT, CONTINUE, BRAKE, BRAKE F, RESUME, or RETURN with an optional value.</summary>
internal sealed class KrlJump(int line, string keyword, KrlExpr? value) : KrlStmt(line)
{
    /// <summary>EXIT, HALT, CONTINUE, BRAKE, BRAKE F, RESUME or RETURN.</summary>
    public string Keyword { get; } = keyword;

    /// <summary>RETURN's value in a function (null otherwise).</summary>
    public KrlExpr? Value { get; } = value;
}

/// <summary>[GLOBAL] INTERRUPT DECL priority WHEN condition DO call.</summary>
internal sealed class KrlInterruptDecl(int line, int priority, KrlExpr condition, KrlCall handler) : KrlStmt(line)
{
    /// <summary>The interrupt's number (its priority).</summary>
    public int Priority { get; } = priority;

    /// <summary>The event: the handler runs when it becomes TRUE.</summary>
    public KrlExpr Condition { get; } = condition;

    /// <summary>The subprogram called.</summary>
    public KrlCall Handler { get; } = handler;

    /// <summary>True when every variable the condition reads is woken on change (set when the program is loaded, see <see cref="KrlWaitWake"/>).</summary>
    public bool Woken { get; set; }
}

/// <summary>INTERRUPT ON / OFF / ENABLE / DISABLE [priority].</summary>
internal sealed class KrlInterruptSwitch(int line, string action, int? priority) : KrlStmt(line)
{
    /// <summary>ON, OFF, ENABLE or DISABLE.</summary>
    public string Action { get; } = action;

    /// <summary>The interrupt, or null for all.</summary>
    public int? Priority { get; } = priority;
}
