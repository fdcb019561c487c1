namespace Machina.Simulation.Rapid;

/// <summary>A statement of a RAPID routine.</summary>
internal abstract class RapidStmt(int line)
{
    /// <summary>The line of the statement.</summary>
    public int Line { get; } = line;
}

/// <summary><c>target := value;</c></summary>
internal sealed class RapidAssign(int line, RapidExpr target, RapidExpr value) : RapidStmt(line)
{
    /// <summary>The data written.</summary>
    public RapidExpr Target { get; } = target;

    /// <summary>The value.</summary>
    public RapidExpr Value { get; } = value;
}

/// <summary>A procedure call (an instruction): <c>MoveL p, v100, z5, tool0;</c></summary>
internal sealed class RapidProcCall(int line, string name, RapidArg[] args) : RapidStmt(line)
{
    /// <summary>The procedure's name.</summary>
    public string Name { get; } = name;

    /// <summary>The arguments.</summary>
    public RapidArg[] Args { get; } = args;

    /// <summary>What the binder found: a built-in or a user routine.</summary>
    public RapidCallTarget? Target { get; set; }
}

/// <summary><c>IF … THEN … ELSEIF … ELSE … ENDIF</c> (and the compact <c>IF cond statement</c>).</summary>
internal sealed class RapidIf(int line, List<(RapidExpr Condition, List<RapidStmt> Body)> branches, List<RapidStmt>? otherwise) : RapidStmt(line)
{
    /// <summary>Each condition with its statements, in order.</summary>
    public List<(RapidExpr Condition, List<RapidStmt> Body)> Branches { get; } = branches;

    /// <summary>The ELSE statements, or null.</summary>
    public List<RapidStmt>? Otherwise { get; } = otherwise;
}

/// <summary><c>WHILE cond DO … ENDWHILE</c></summary>
internal sealed class RapidWhile(int line, RapidExpr condition, List<RapidStmt> body) : RapidStmt(line)
{
    /// <summary>The condition.</summary>
    public RapidExpr Condition { get; } = condition;

    /// <summary>The loop body.</summary>
    public List<RapidStmt> Body { get; } = body;
}

/// <summary><c>FOR i FROM a TO b [STEP s] DO … ENDFOR</c>: the loop variable is a num of the loop alone.</summary>
internal sealed class RapidFor(int line, string variable, RapidExpr from, RapidExpr to, RapidExpr? step, List<RapidStmt> body) : RapidStmt(line)
{
    /// <summary>The loop variable's name.</summary>
    public string Variable { get; } = variable;

    /// <summary>The first value.</summary>
    public RapidExpr From { get; } = from;

    /// <summary>The last value.</summary>
    public RapidExpr To { get; } = to;

    /// <summary>The step (1 or -1 by default, towards <see cref="To"/>).</summary>
    public RapidExpr? Step { get; } = step;

    /// <summary>The loop body.</summary>
    public List<RapidStmt> Body { get; } = body;

    /// <summary>The loop variable's local slot, set by the binder.</summary>
    public int Slot { get; set; } = -1;
}

/// <summary><c>TEST e CASE a, b: … DEFAULT: … ENDTEST</c></summary>
internal sealed class RapidTest(int line, RapidExpr value, List<(RapidExpr[] Values, List<RapidStmt> Body)> cases, List<RapidStmt>? otherwise) : RapidStmt(line)
{
    /// <summary>The value tested.</summary>
    public RapidExpr Value { get; } = value;

    /// <summary>Each CASE with its values and statements.</summary>
    public List<(RapidExpr[] Values, List<RapidStmt> Body)> Cases { get; } = cases;

    /// <summary>The DEFAULT statements, or null.</summary>
    public List<RapidStmt>? Otherwise { get; } = otherwise;

    /// <summary>
    /// When every CASE value is a number literal: the index of the first CASE of each number, so that a num value finds its CASE in
    /// one look-up instead of one comparison per value (literals have no side effects, and = compares numbers exactly); else null.
    /// </summary>
    public Dictionary<double, int>? NumberCases { get; } = NumberCasesOf(cases);

    private static Dictionary<double, int>? NumberCasesOf(List<(RapidExpr[] Values, List<RapidStmt> Body)> cases)
    {
        var lookup = new Dictionary<double, int>();
        for (int k = 0; k < cases.Count; k++)
        {
            foreach (RapidExpr value in cases[k].Values)
            {
                if (value is not RapidLiteral { Value: double number } || double.IsNaN(number))
                {
                    return null;
                }
                lookup.TryAdd(number == 0 ? 0.0 : number, k); // -0 is 0 (= finds it); the first CASE of a number wins
            }
        }
        return lookup;
    }
}

/// <summary>What a simple control statement does.</summary>
internal enum RapidJumpKind
{
    /// <summary><c>GOTO label</c></summary>
    Goto,

    /// <summary><c>label:</c></summary>
    Label,

    /// <summary><c>RETURN [value]</c></summary>
    Return,

    /// <summary><c>EXIT</c>: the program ends (it must be started from main again).</summary>
    Exit,

    /// <summary><c>Stop</c>: the program stops and can be started again where it stopped.</summary>
    Stop,

    /// <summary><c>RETRY</c> (error handlers): runs the statement that failed again.</summary>
    Retry,

    /// <summary><c>TRYNEXT</c> (error handlers): goes on after the statement that failed.</summary>
    TryNext,

    /// <summary><c>RAISE [errno]</c>: raises an error, or passes the one being handled to the caller.</summary>
    Raise,
}

/// <summary>A control statement: GOTO, a label, RETURN, EXIT, Stop, RETRY, TRYNEXT, RAISE.</summary>
internal sealed class RapidJump(int line, RapidJumpKind kind, string? label = null, RapidExpr? value = null) : RapidStmt(line)
{
    /// <summary>What it does.</summary>
    public RapidJumpKind Kind { get; } = kind;

    /// <summary>The label of a GOTO or label statement.</summary>
    public string? Label { get; } = label;

    /// <summary>The value of RETURN or RAISE, or null.</summary>
    public RapidExpr? Value { get; } = value;
}

/// <summary><c>CONNECT intnum WITH trap;</c></summary>
internal sealed class RapidConnect(int line, RapidExpr interrupt, string trap) : RapidStmt(line)
{
    /// <summary>The interrupt number variable.</summary>
    public RapidExpr Interrupt { get; } = interrupt;

    /// <summary>The trap routine's name.</summary>
    public string Trap { get; } = trap;

    /// <summary>The trap routine, set by the binder.</summary>
    public RapidRoutine? Routine { get; set; }
}

/// <summary>A late-bound procedure call, <c>%"proc" + name% args;</c>: the procedure is found by its name when the statement runs.</summary>
internal sealed class RapidLateCall(int line, RapidExpr name, RapidArg[] args) : RapidStmt(line)
{
    /// <summary>The string expression that names the procedure.</summary>
    public RapidExpr Name { get; } = name;

    /// <summary>The arguments.</summary>
    public RapidArg[] Args { get; } = args;

    /// <summary>The last procedure this call resolved to, with its argument map (most late calls name the same few procedures).</summary>
    public RapidCallTarget? Last { get; set; }
}
