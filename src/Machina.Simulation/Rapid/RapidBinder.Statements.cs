namespace Machina.Simulation.Rapid;

/// <summary>Routines and statements.</summary>
internal sealed partial class RapidBinder
{
    private void BindRoutine(RapidRoutine routine)
    {
        var scope = new RapidScope(routine);
        routine.WritesParameter = new bool[routine.Parameters.Count];
        routine.TakesValuesOnly = routine.Parameters.TrueForAll(p => p.Mode == RapidParamMode.In);
        foreach (RapidParam p in routine.Parameters)
        {
            if (scope.DeclaredHere(p.Name))
            {
                throw Refuse(routine.Line, RapidLoadException.Reference($"the parameter '{p.Name}' is declared twice"));
            }
            RapidType type = p.IsSwitch ? RapidTypes.Bool : TypeNamed(p.TypeName, routine.Line);
            scope.Add(p.Name, new RapidDataType(type, p.Rank), readOnly: false);
        }
        foreach (RapidDataDecl decl in routine.Data)
        {
            if (scope.DeclaredHere(decl.Name))
            {
                throw Refuse(decl.Line, RapidLoadException.Reference($"'{decl.Name}' is already defined"));
            }
            if (decl.Storage == RapidStorage.Pers)
            {
                throw Refuse(decl.Line, RapidLoadException.Syntax("PERS data cannot be declared in a routine"));
            }
            var type = new RapidDataType(TypeNamed(decl.TypeName, decl.Line), decl.Dimensions.Length);
            Dimensions(decl, scope);
            if (decl.Initial is not null)
            {
                BindValue(decl.Initial, type, scope);
            }
            scope.Add(decl.Name, type, decl.Storage == RapidStorage.Const);
        }
        CollectLabels(routine.Body, scope.Labels);
        BindBlock(routine.Body, scope);
        if (routine.ErrorHandler is { } handler)
        {
            scope.InErrorHandler = true;
            CollectLabels(handler, scope.Labels);
            BindBlock(handler, scope);
            scope.InErrorHandler = false;
        }
        foreach (RapidExpr errorNumber in routine.ErrorList ?? [])
        {
            BindValue(errorNumber, NumType, scope);
        }
        if (routine.UndoHandler is { } undo)
        {
            CollectLabels(undo, scope.Labels);
            BindBlock(undo, scope);
        }
        routine.FrameSize = routine.SlotTypes.Count;
    }

    private static void CollectLabels(List<RapidStmt> body, HashSet<string> labels)
    {
        foreach (RapidStmt s in body)
        {
            switch (s)
            {
                case RapidJump { Kind: RapidJumpKind.Label } label:
                    labels.Add(label.Label!);
                    break;
                case RapidIf i:
                    i.Branches.ForEach(b => CollectLabels(b.Body, labels));
                    if (i.Otherwise is not null)
                    {
                        CollectLabels(i.Otherwise, labels);
                    }
                    break;
                case RapidWhile w:
                    CollectLabels(w.Body, labels);
                    break;
                case RapidFor f:
                    CollectLabels(f.Body, labels);
                    break;
                case RapidTest t:
                    t.Cases.ForEach(c => CollectLabels(c.Body, labels));
                    if (t.Otherwise is not null)
                    {
                        CollectLabels(t.Otherwise, labels);
                    }
                    break;
            }
        }
    }

    private void BindBlock(List<RapidStmt> body, RapidScope scope)
    {
        foreach (RapidStmt s in body)
        {
            BindStatement(s, scope);
        }
    }

    private void BindStatement(RapidStmt statement, RapidScope scope)
    {
        switch (statement)
        {
            case RapidAssign a:
            {
                RapidDataType? target = BindTarget(a.Target, scope, "assigned");
                BindValue(a.Value, target, scope);
                break;
            }
            case RapidProcCall call:
                call.Target = BindCall(call.Name, call.Args, call.Line, scope, procedure: true);
                break;
            case RapidIf i:
                foreach ((RapidExpr condition, List<RapidStmt> body) in i.Branches)
                {
                    BindValue(condition, new RapidDataType(RapidTypes.Bool), scope);
                    BindBlock(body, scope);
                }
                if (i.Otherwise is not null)
                {
                    BindBlock(i.Otherwise, scope);
                }
                break;
            case RapidWhile w:
                BindValue(w.Condition, new RapidDataType(RapidTypes.Bool), scope);
                BindBlock(w.Body, scope);
                break;
            case RapidFor f:
            {
                var num = new RapidDataType(RapidTypes.Num);
                BindValue(f.From, num, scope);
                BindValue(f.To, num, scope);
                if (f.Step is not null)
                {
                    BindValue(f.Step, num, scope);
                }
                scope.Push();
                f.Slot = scope.Add(f.Variable, num, readOnly: true);
                BindBlock(f.Body, scope);
                scope.Pop();
                break;
            }
            case RapidTest t:
            {
                RapidDataType? type = BindExpression(t.Value, null, scope);
                foreach ((RapidExpr[] values, List<RapidStmt> body) in t.Cases)
                {
                    foreach (RapidExpr v in values)
                    {
                        BindValue(v, type, scope);
                    }
                    BindBlock(body, scope);
                }
                if (t.Otherwise is not null)
                {
                    BindBlock(t.Otherwise, scope);
                }
                break;
            }
            case RapidJump j:
                BindJump(j, scope);
                break;
            case RapidLateCall late:
                BindValue(late.Name, new RapidDataType(RapidTypes.String), scope);
                foreach (RapidArg arg in late.Args)
                {
                    if (arg.Value is not null)
                    {
                        BindExpression(arg.Value, null, scope);
                        if (arg.Value is RapidName name)
                        {
                            NoteWrite(name, scope); // the procedure is known when the call runs: it may take the data by reference
                        }
                    }
                }
                break;
            case RapidConnect c:
            {
                RapidDataType? type = BindTarget(c.Interrupt, scope, "connected");
                if (type is { } t && !t.Element.Name.Equals("intnum", StringComparison.OrdinalIgnoreCase))
                {
                    throw Refuse(c.Line, RapidLoadException.Type($"CONNECT needs an intnum variable, not a {t}"));
                }
                c.Routine = RoutineNamed(c.Trap) is { Kind: RapidRoutineKind.Trap } trap
                    ? trap
                    : throw Refuse(c.Line, RapidLoadException.Reference($"'{c.Trap}' is not a trap routine"));
                break;
            }
        }
    }

    private void BindJump(RapidJump j, RapidScope scope)
    {
        RapidRoutine routine = scope.Routine!;
        switch (j.Kind)
        {
            case RapidJumpKind.Goto when !scope.Labels.Contains(j.Label!):
                throw Refuse(j.Line, RapidLoadException.Reference($"the label '{j.Label}' is not in this routine"));
            case RapidJumpKind.Return when routine.Kind == RapidRoutineKind.Func && j.Value is null:
                throw Refuse(j.Line, RapidLoadException.Syntax($"the function '{routine.Name}' must return a value"));
            case RapidJumpKind.Return when routine.Kind != RapidRoutineKind.Func && j.Value is not null:
                throw Refuse(j.Line, RapidLoadException.Syntax($"the routine '{routine.Name}' is not a function: RETURN takes no value"));
            case RapidJumpKind.Return when j.Value is not null:
                BindValue(j.Value, routine.ReturnType, scope);
                break;
            case RapidJumpKind.Retry or RapidJumpKind.TryNext when !scope.InErrorHandler:
                throw Refuse(j.Line, RapidLoadException.Syntax($"{j.Kind.ToString().ToUpperInvariant()} is allowed in an error handler only"));
            case RapidJumpKind.Raise when j.Value is null && !scope.InErrorHandler:
                throw Refuse(j.Line, RapidLoadException.Syntax("RAISE without an error number is allowed in an error handler only"));
            case RapidJumpKind.Raise when j.Value is not null:
                BindValue(j.Value, new RapidDataType(RapidTypes.Num), scope);
                break;
        }
    }
}
