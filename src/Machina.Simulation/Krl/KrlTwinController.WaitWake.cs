namespace Machina.Simulation.Krl;

/// <summary>
/// Marks, when a program is loaded, the variables that its WAIT FOR and interrupt conditions read, so that their writes wake a
/// waiting WAIT FOR (<see cref="KrlWaitWake"/>), and notes which conditions need the interpreter cycle's look instead.
/// </summary>
internal sealed partial class KrlTwinController
{
    /// <summary>Wakes a waiting WAIT FOR when a variable a condition reads is written.</summary>
    public KrlWaitWake WaitWake => _waitWake ??= new KrlWaitWake(Io);

    private KrlWaitWake? _waitWake;

    /// <summary>How many times a WAIT FOR looked at its condition again after waiting (the interpreters' wake-ups while they wait).</summary>
    public long WaitForLooks => Interlocked.Read(ref _waitForLooks);

    private long _waitForLooks;

    /// <summary>Marks the conditions of every WAIT FOR and INTERRUPT DECL of <paramref name="modules"/> (bound already).</summary>
    private void MarkWaitConditions(IEnumerable<KrlModule> modules)
    {
        foreach (KrlModule module in modules)
        {
            foreach (KrlRoutine routine in module.Routines)
            {
                MarkWaitConditions(routine.Body);
            }
        }
    }

    private void MarkWaitConditions(List<KrlStmt> statements)
    {
        foreach (KrlStmt statement in statements)
        {
            switch (statement)
            {
                case KrlWait { ForCondition: true } wait:
                    wait.Woken = Woken(wait.Value);
                    break;
                case KrlInterruptDecl declaration:
                    declaration.Woken = Woken(declaration.Condition);
                    break;
                case KrlIf branch:
                    MarkWaitConditions(branch.Then);
                    MarkWaitConditions(branch.Else);
                    break;
                case KrlLoop loop:
                    MarkWaitConditions(loop.Body);
                    break;
                case KrlFor loop:
                    MarkWaitConditions(loop.Body);
                    break;
                case KrlSwitch choice:
                    foreach ((_, List<KrlStmt> body) in choice.Cases)
                    {
                        MarkWaitConditions(body);
                    }
                    MarkWaitConditions(choice.Default ?? []);
                    break;
            }
        }
    }

    /// <summary>
    /// Marks the variables <paramref name="condition"/> reads; true when a change of each wakes a waiting WAIT FOR: a data list's
    /// variable (a program writes it), a local (only its own interpreter writes it, between two looks), $FLAG (programs, and the
    /// controller's <see cref="SetFlag"/>), the IO arrays (the host's inputs, the programs' outputs) and read-only system
    /// variables the controller does not compute. False for a function call, a computed system variable ($TIMER, $POS_ACT) and
    /// any other system variable (the controller may write those without a wake-up).
    /// </summary>
    private bool Woken(KrlExpr condition) => condition switch
    {
        KrlLiteral => true,
        KrlName { Slot: >= 0 } => true,
        KrlName { Cell: { } cell } => WokenCell(cell),
        KrlIndex index => index.Indices.Aggregate(Woken(index.Target), (woken, i) => (i is null || Woken(i)) & woken),
        KrlMember member => Woken(member.Target),
        KrlUnary unary => Woken(unary.Operand),
        KrlBinary binary => Woken(binary.Left) & Woken(binary.Right),
        _ => false,
    };

    private bool WokenCell(KrlCell cell)
    {
        cell.WakeOnWrite(WaitWake);
        if (cell.Signals is not null)
        {
            return true;
        }
        bool system = Environment.System.TryGetValue(cell.Name, out KrlCell? known) && ReferenceEquals(known, cell);
        bool signal = Environment.Signals.TryGetValue(cell.Name, out known) && ReferenceEquals(known, cell);
        return cell.Read is null && !signal && (!system || cell.ReadOnly || ReferenceEquals(cell, FlagCell));
    }
}
