namespace Machina.Simulation.Krl;

/// <summary>KRL statements: control structures, waits, motions, interrupts, assignments and calls.</summary>
internal sealed partial class KrlParser
{
    private static readonly string[] Approximations = ["C_PTP", "C_DIS", "C_ORI", "C_VEL"];

    private KrlStmt Statement()
    {
        KrlToken token = Peek;
        int line = token.Line;
        if (token.Kind != KrlTokenKind.Name)
        {
            throw Error(token, $"a statement cannot start with {token.Display}");
        }
        switch (token.Text.ToUpperInvariant())
        {
            case "IF":
            {
                _at++;
                KrlExpr condition = Expression();
                Expect("THEN");
                EndOfLine();
                List<KrlStmt> then = Block("ELSE", "ENDIF");
                List<KrlStmt> otherwise = [];
                if (Accept("ELSE"))
                {
                    EndOfLine();
                    otherwise = Block("ENDIF");
                }
                Expect("ENDIF");
                EndOfLine();
                return new KrlIf(line, condition, then, otherwise);
            }
            case "WHILE":
            {
                _at++;
                KrlExpr condition = Expression();
                EndOfLine();
                List<KrlStmt> body = Block("ENDWHILE");
                Expect("ENDWHILE");
                EndOfLine();
                return new KrlLoop(line, KrlLoopKind.While, condition, body);
            }
            case "REPEAT":
            {
                _at++;
                EndOfLine();
                List<KrlStmt> body = Block("UNTIL");
                Expect("UNTIL");
                KrlExpr condition = Expression();
                EndOfLine();
                return new KrlLoop(line, KrlLoopKind.Repeat, condition, body);
            }
            case "LOOP":
            {
                _at++;
                EndOfLine();
                List<KrlStmt> body = Block("ENDLOOP");
                Expect("ENDLOOP");
                EndOfLine();
                return new KrlLoop(line, KrlLoopKind.Loop, null, body);
            }
            case "FOR":
            {
                _at++;
                var counter = new KrlName(Peek.Line, Identifier("the FOR counter"));
                Expect("=");
                KrlExpr from = Expression();
                Expect("TO");
                KrlExpr to = Expression();
                KrlExpr? step = Accept("STEP") ? Expression() : null;
                EndOfLine();
                List<KrlStmt> body = Block("ENDFOR");
                Expect("ENDFOR");
                EndOfLine();
                return new KrlFor(line, counter, from, to, step, body);
            }
            case "SWITCH":
                return Switch();
            case "WAIT":
            {
                _at++;
                if (Accept("SEC"))
                {
                    KrlExpr seconds = Expression();
                    EndOfLine();
                    return new KrlWait(line, false, seconds);
                }
                Expect("FOR");
                KrlExpr condition = Expression();
                EndOfLine();
                return new KrlWait(line, true, condition);
            }
            case "PTP":
            case "LIN":
            case "CIRC":
                return Motion();
            case "BRAKE":
            {
                // BRAKE, or BRAKE F (the path-maintaining stop of an emergency brake ramp): the twin stops the same way for both
                _at++;
                bool fast = Peek.Is("F");
                if (fast)
                {
                    _at++;
                }
                EndOfLine();
                return new KrlJump(line, fast ? "BRAKE F" : "BRAKE", null);
            }
            case "EXIT":
            case "HALT":
            case "CONTINUE":
            case "RESUME":
                _at++;
                EndOfLine();
                return new KrlJump(line, token.Text.ToUpperInvariant(), null);
            case "RETURN":
            {
                _at++;
                KrlExpr? value = Peek.Kind is KrlTokenKind.EndOfLine or KrlTokenKind.End ? null : Expression();
                EndOfLine();
                return new KrlJump(line, "RETURN", value);
            }
            case "GLOBAL":
            case "INTERRUPT":
                return Interrupt();
            case "TRIGGER":
                return Trigger();
            case "CONFIRM":
            {
                // Acknowledges a message (CONFIRM number, 0: all acknowledgeable ones): the twin keeps none to acknowledge.
                _at++;
                KrlExpr handle = Expression();
                EndOfLine();
                return new KrlJump(line, "CONFIRM", handle);
            }
            case "GOTO":
                return Goto();
            default:
                if (IsLabel())
                {
                    return Label();
                }
                if (KrlKeywords.IsReserved(token.Text))
                {
                    throw Error(token, $"{token.Text.ToUpperInvariant()} cannot start a statement here");
                }
                return Simple();
        }
    }

    private List<KrlStmt> Block(params string[] ends)
    {
        Deeper();
        var body = new List<KrlStmt>();
        while (!ends.Any(e => Peek.Is(e)))
        {
            if (Peek.Kind == KrlTokenKind.End || Peek.Is("END") || Peek.Is("ENDFCT"))
            {
                throw Error(Peek, $"{ends[^1]} is missing");
            }
            if (IsDeclaration())
            {
                throw Error(Peek, "a declaration must come before the first statement of the routine");
            }
            body.Add(Statement());
        }
        _nesting--;
        return body;
    }

    private KrlSwitch Switch()
    {
        int line = Peek.Line;
        _at++;
        KrlExpr selector = Expression();
        EndOfLine();
        var cases = new List<(List<KrlExpr>, List<KrlStmt>)>();
        List<KrlStmt>? otherwise = null;
        while (!Peek.Is("ENDSWITCH"))
        {
            if (Accept("CASE"))
            {
                var values = new List<KrlExpr>();
                do
                {
                    values.Add(Expression());
                }
                while (Accept(","));
                EndOfLine();
                cases.Add((values, Block("CASE", "DEFAULT", "ENDSWITCH")));
            }
            else if (Peek.Is("DEFAULT") && otherwise is null)
            {
                _at++;
                EndOfLine();
                otherwise = Block("CASE", "ENDSWITCH");
            }
            else
            {
                throw Error(Peek, $"expected CASE, DEFAULT or ENDSWITCH, found {Peek.Display}");
            }
        }
        if (cases.Count == 0)
        {
            throw Error(Peek, "a SWITCH needs at least one CASE");
        }
        _at++;
        EndOfLine();
        return new KrlSwitch(line, selector, cases, otherwise);
    }

    private KrlMotion Motion()
    {
        KrlToken keyword = Peek;
        _at++;
        string kind = keyword.Text.ToUpperInvariant();
        KrlExpr? auxiliary = null;
        if (kind == "CIRC")
        {
            auxiliary = Expression();
            Expect(",");
        }
        KrlExpr target = Expression();
        if (kind == "CIRC" && Peek.IsSymbol(","))
        {
            throw Error(Peek, "CIRC with a circular angle (CA) is not supported by the twin");
        }
        string? approximation = null;
        if (Peek.Kind == KrlTokenKind.Name && Approximations.Any(a => Peek.Is(a)))
        {
            approximation = Peek.Text.ToUpperInvariant();
            if (kind == "PTP" ? approximation != "C_PTP" && approximation != "C_DIS" : approximation == "C_PTP")
            {
                throw Error(Peek, $"{kind} cannot be approximated with {approximation}");
            }
            _at++;
            if (approximation == "C_PTP" && Peek.Kind == KrlTokenKind.Name && Approximations.Any(a => Peek.Is(a)))
            {
                // PTP-CP approximation (PTP P1 C_PTP C_DIS): C_PTP for a PTP that follows, the second for a LIN or CIRC that follows.
                string path = Peek.Text.ToUpperInvariant();
                if (path == "C_PTP")
                {
                    throw Error(Peek, "PTP … C_PTP takes C_DIS, C_ORI or C_VEL after it (for a LIN or CIRC that follows), not C_PTP again");
                }
                approximation += " " + path;
                _at++;
            }
        }
        EndOfLine();
        return new KrlMotion(keyword.Line, kind, target, auxiliary, approximation);
    }

    private KrlStmt Interrupt()
    {
        int line = Peek.Line;
        bool global = Accept("GLOBAL");
        Expect("INTERRUPT");
        if (Accept("DECL"))
        {
            KrlToken priority = Peek;
            if (priority.Kind != KrlTokenKind.Int)
            {
                throw Error(priority, $"an interrupt's priority is a whole number, not {priority.Display}");
            }
            _at++;
            Expect("WHEN");
            KrlExpr condition = Expression();
            Expect("DO");
            KrlExpr handler = Postfix();
            if (handler is not KrlCall call)
            {
                throw Error(Peek, "an interrupt's DO calls a subprogram: name( … )");
            }
            EndOfLine();
            return new KrlInterruptDecl(line, Whole(priority), condition, call);
        }
        if (global)
        {
            throw Error(Peek, "GLOBAL here must be followed by INTERRUPT DECL");
        }
        KrlToken action = Peek;
        if (!(action.Is("ON") || action.Is("OFF") || action.Is("ENABLE") || action.Is("DISABLE")))
        {
            throw Error(action, $"expected DECL, ON, OFF, ENABLE or DISABLE after INTERRUPT, found {action.Display}");
        }
        _at++;
        int? number = null;
        if (Peek.Kind == KrlTokenKind.Int)
        {
            number = Whole(Peek);
            _at++;
        }
        EndOfLine();
        return new KrlInterruptSwitch(line, action.Text.ToUpperInvariant(), number);
    }

    private KrlStmt Simple()
    {
        int line = Peek.Line;
        KrlExpr target = Postfix();
        if (target is KrlCall call && Peek.Kind is KrlTokenKind.EndOfLine or KrlTokenKind.End)
        {
            EndOfLine();
            return new KrlCallStmt(line, call);
        }
        if (target is KrlCall)
        {
            throw Error(Peek, $"unexpected {Peek.Display} after a call");
        }
        if (!Peek.IsSymbol("="))
        {
            throw Error(Peek, Peek.Kind is KrlTokenKind.EndOfLine or KrlTokenKind.End
                ? "incomplete statement: expected '=' and a value, or a call with ( )"
                : Peek.IsSymbol("==") ? "'==' compares; an assignment is written with '='" : $"expected '=', found {Peek.Display}");
        }
        _at++;
        KrlExpr value = Expression();
        EndOfLine();
        return new KrlAssign(line, target, value);
    }
}
