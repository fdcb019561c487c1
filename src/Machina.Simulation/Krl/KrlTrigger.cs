namespace Machina.Simulation.Krl;

/// <summary>
/// <c>TRIGGER WHEN DISTANCE = d DELAY = t DO action [PRIO = p]</c> (or <c>WHEN PATH = …</c>): an assignment or a call bound to
/// the next motion. The twin runs it when that motion starts (DISTANCE = 0) or when it has reached its end point (DISTANCE = 1,
/// PATH); DELAY and PRIO are read and left out (the twin has no path-time offset).
/// </summary>
internal sealed class KrlTrigger(int line, bool atEnd, KrlExpr distance, KrlExpr delay, KrlStmt action) : KrlStmt(line)
{
    /// <summary>True when the action runs at the end point (DISTANCE = 1 or PATH), false at the start (DISTANCE = 0).</summary>
    public bool AtEnd { get; } = atEnd;

    /// <summary>DISTANCE's or PATH's value.</summary>
    public KrlExpr Distance { get; } = distance;

    /// <summary>DELAY's value (milliseconds).</summary>
    public KrlExpr Delay { get; } = delay;

    /// <summary>The assignment or call.</summary>
    public KrlStmt Action { get; } = action;
}

/// <summary>Reading TRIGGER.</summary>
internal sealed partial class KrlParser
{
    private KrlTrigger Trigger()
    {
        KrlToken keyword = Peek;
        _at++;
        Expect("WHEN");
        KrlToken where = Peek;
        if (!(where.Is("DISTANCE") || where.Is("PATH")))
        {
            throw Error(where, $"TRIGGER WHEN takes DISTANCE or PATH, not {where.Display}");
        }
        _at++;
        Expect("=");
        KrlExpr distance = Expression();
        Expect("DELAY");
        Expect("=");
        KrlExpr delay = Expression();
        Expect("DO");
        int line = Peek.Line;
        KrlExpr target = Postfix();
        KrlStmt action;
        if (target is KrlCall call)
        {
            action = new KrlCallStmt(line, call);
        }
        else
        {
            Expect("=");
            action = new KrlAssign(line, target, Expression());
        }
        if (Accept("PRIO"))
        {
            Expect("=");
            Expression();
        }
        EndOfLine();
        bool atStart = where.Is("DISTANCE") && distance is KrlLiteral { Value: int or double } literal && KrlValues.ToReal(literal.Value) == 0;
        return new KrlTrigger(keyword.Line, !atStart, distance, delay, action);
    }
}
