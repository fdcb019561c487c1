namespace Machina.Simulation.Krl;

/// <summary>
/// Checks a loaded program as the controller does before it runs: every name is declared (a local, the module's data list, a
/// PUBLIC data list's GLOBAL variable, a system variable, a configured signal, a routine or a built-in), every value has the
/// type its place needs. The first mistake refuses the program with its file and line.
/// </summary>
internal sealed partial class KrlBinder(IReadOnlyDictionary<string, KrlModule> modules, KrlEnvironment environment)
{
    private KrlModule? _module;
    private KrlRoutine? _routine;
    private string _file = "";

    /// <summary>The string literals of the program by their text (ordinal): one string per text.</summary>
    private readonly Dictionary<string, string> _texts = new(StringComparer.Ordinal);

    /// <summary>Binds every routine of every module.</summary>
    public void BindAll()
    {
        foreach (KrlModule module in modules.Values)
        {
            _module = module;
            foreach (KrlRoutine routine in module.Routines)
            {
                _routine = routine;
                _file = routine.File;
                Block(routine.Body, 0);
            }
        }
    }

    /// <summary>The routine called <paramref name="name"/> from <paramref name="module"/>: its own, then GLOBAL ones and the main routines of other files.</summary>
    public static KrlRoutine? FindRoutine(IReadOnlyDictionary<string, KrlModule> modules, KrlModule? module, string name)
    {
        KrlRoutine? own = module?.Routines.FirstOrDefault(r => Same(r.Name, name));
        if (own is not null)
        {
            return own;
        }
        foreach (KrlModule other in modules.Values)
        {
            KrlRoutine? found = other.Routines.FirstOrDefault(r => r.IsGlobal && Same(r.Name, name));
            if (found is not null)
            {
                return found;
            }
        }
        return null;
    }

    private static bool Same(string a, string b) => string.Equals(a, b, StringComparison.OrdinalIgnoreCase);

    /// <summary>Checks the initial value of a data list variable (no routine's locals are visible).</summary>
    public void BindConstant(string file, KrlExpr value, KrlType type)
    {
        _module = null;
        _routine = null;
        _file = file;
        Require(type, value, "the initial value");
    }

    private KrlLoadException Error(int line, string reason) => new(_file, line, reason);

    private void Block(List<KrlStmt> body, int loops)
    {
        foreach (KrlStmt statement in body)
        {
            Statement(statement, loops);
        }
    }

    private void Statement(KrlStmt statement, int loops)
    {
        switch (statement)
        {
            case KrlAssign assign:
                Assign(assign.Target, assign.Value, assign.Line);
                break;
            case KrlCallStmt call:
                Call(call.Call, statement: true);
                break;
            case KrlIf branch:
                Condition(branch.Condition, "IF");
                Block(branch.Then, loops);
                Block(branch.Else, loops);
                break;
            case KrlLoop loop:
                if (loop.Condition is not null)
                {
                    Condition(loop.Condition, loop.Kind == KrlLoopKind.While ? "WHILE" : "UNTIL");
                }
                Block(loop.Body, loops + 1);
                break;
            case KrlFor loop:
                if (Expr(loop.Counter, null).Kind != KrlKind.Int)
                {
                    throw Error(loop.Line, $"the FOR counter {loop.Counter.Name} must be an INT, not {loop.Counter.Type}");
                }
                foreach (KrlExpr bound in new[] { loop.From, loop.To, loop.Step }.OfType<KrlExpr>())
                {
                    if (!Expr(bound, null).IsNumber)
                    {
                        throw Error(loop.Line, $"a FOR bound must be a number, not {bound.Type}");
                    }
                }
                Block(loop.Body, loops + 1);
                break;
            case KrlSwitch choice:
            {
                KrlType selector = Expr(choice.Selector, null);
                if (selector.Kind is not (KrlKind.Int or KrlKind.Char or KrlKind.Enum))
                {
                    throw Error(choice.Line, $"SWITCH selects on an INT, CHAR or ENUM value, not {selector}");
                }
                foreach ((List<KrlExpr> values, List<KrlStmt> caseBody) in choice.Cases)
                {
                    foreach (KrlExpr value in values)
                    {
                        if (Expr(value, selector).Kind != selector.Kind)
                        {
                            throw Error(value.Line, $"a CASE value must be of the SWITCH's type {selector}, not {value.Type}");
                        }
                    }
                    Block(caseBody, loops);
                }
                if (choice.Default is not null)
                {
                    Block(choice.Default, loops);
                }
                break;
            }
            case KrlWait wait:
                if (wait.ForCondition)
                {
                    Condition(wait.Value, "WAIT FOR");
                }
                else if (!Expr(wait.Value, null).IsNumber)
                {
                    throw Error(wait.Line, $"WAIT SEC needs a number of seconds, not {wait.Value.Type}");
                }
                break;
            case KrlMotion motion:
                Motion(motion);
                break;
            case KrlTrigger trigger:
                if (!Expr(trigger.Distance, null).IsNumber || !Expr(trigger.Delay, null).IsNumber)
                {
                    throw Error(trigger.Line, "TRIGGER's DISTANCE (or PATH) and DELAY are numbers");
                }
                Statement(trigger.Action, loops);
                break;
            case KrlJump jump:
                Jump(jump, loops);
                break;
            case KrlInterruptDecl declaration:
                Condition(declaration.Condition, "WHEN");
                Call(declaration.Handler, statement: true);
                if (declaration.Priority is < 1 or > 128)
                {
                    throw Error(declaration.Line, $"an interrupt's priority is 1 to 128, not {declaration.Priority}");
                }
                break;
            case KrlInterruptSwitch:
            case KrlLabel:
                break;
            case KrlGoto jump when !KrlLabel.Within(_routine!.Body, jump.Label):
                throw Error(jump.Line, $"GOTO {jump.Label}: the routine {_routine.Name} has no label {jump.Label}:");
            case KrlGoto:
                break;
            default:
                throw Error(statement.Line, "a statement the twin does not know");
        }
    }

    private void Jump(KrlJump jump, int loops)
    {
        if (jump.Keyword == "EXIT" && loops == 0)
        {
            throw Error(jump.Line, "EXIT is only allowed inside a loop");
        }
        if (jump.Keyword == "CONFIRM" && !Expr(jump.Value!, null).IsNumber)
        {
            throw Error(jump.Line, $"CONFIRM takes a message handle (INT), not {jump.Value!.Type}");
        }
        if (jump.Keyword != "RETURN")
        {
            return;
        }
        if (_routine!.ReturnType is { } returns)
        {
            if (jump.Value is null)
            {
                throw Error(jump.Line, $"the function {_routine.Name} must RETURN a {returns} value");
            }
            Require(returns, jump.Value, "RETURN");
        }
        else if (jump.Value is not null)
        {
            throw Error(jump.Line, $"{_routine!.Name} is a subprogram (DEF): its RETURN has no value");
        }
    }

    private void Motion(KrlMotion motion)
    {
        foreach (KrlExpr point in new[] { motion.Target, motion.Auxiliary }.OfType<KrlExpr>())
        {
            KrlType? expected = point is KrlAggregate { TypeName: null } a ? GuessPointType(a) : null;
            KrlType type = Expr(point, expected);
            bool ok = KrlTypes.IsCartesian(type) || (motion.Kind == "PTP" && KrlTypes.IsAxes(type));
            if (!ok)
            {
                throw Error(motion.Line, motion.Kind == "PTP"
                    ? $"PTP moves to an AXIS, E6AXIS, POS, E6POS or FRAME, not {type}"
                    : $"{motion.Kind} moves to a POS, E6POS or FRAME, not {type}");
            }
        }
    }

    /// <summary>An aggregate without a type name in a motion: axes (A1…) or a Cartesian point (X…).</summary>
    private static KrlType GuessPointType(KrlAggregate aggregate) =>
        aggregate.Fields.Count > 0 && KrlTypes.E6Axis.FieldIndex(aggregate.Fields[0].Field) >= 0 && KrlTypes.E6Pos.FieldIndex(aggregate.Fields[0].Field) < 0
            ? KrlTypes.E6Axis
            : KrlTypes.E6Pos;

    private void Condition(KrlExpr condition, string where)
    {
        if (Expr(condition, null).Kind != KrlKind.Bool)
        {
            throw Error(condition.Line, $"the condition of {where} must be BOOL, not {condition.Type}");
        }
    }

    private void Assign(KrlExpr target, KrlExpr value, int line)
    {
        KrlType type = Place(target, "assigned");
        Require(type, value, $"{Describe(target)} =");
        _ = line;
    }

    /// <summary>Checks that <paramref name="value"/> can be stored in a place of <paramref name="type"/>.</summary>
    private void Require(KrlType type, KrlExpr value, string where)
    {
        KrlType actual = Expr(value, type);
        if (value is KrlLiteral { Value: string one } && one.Length == 1 && type.Kind == KrlKind.Char)
        {
            return; // a CHAR constant is written "A"
        }
        if (value is KrlLiteral { Value: string text } && type.IsText)
        {
            if (type.Sizes[0] > 0 && text.Length > type.Sizes[0])
            {
                throw Error(value.Line, $"the string \"{text}\" has {text.Length} characters; {type} holds {type.Sizes[0]}");
            }
            return;
        }
        if (!KrlTypes.Assignable(type, actual))
        {
            throw Error(value.Line, $"type mismatch: {where} needs a {type} value, not {actual}");
        }
    }

    /// <summary>Checks that <paramref name="target"/> is a variable that may be written; returns its type.</summary>
    private KrlType Place(KrlExpr target, string what)
    {
        KrlType type = Expr(target, null);
        KrlExpr root = target;
        while (root is KrlIndex or KrlMember)
        {
            root = root is KrlIndex i ? i.Target : ((KrlMember)root).Target;
        }
        if (root is not KrlName name)
        {
            throw Error(target.Line, $"only a variable can be {what}");
        }
        if (name.Cell is { ReadOnly: true })
        {
            throw Error(target.Line, $"{name.Name} is write-protected: a program can only read it");
        }
        return type;
    }

    private static string Describe(KrlExpr target) => target switch
    {
        KrlName n => n.Name,
        KrlMember m => Describe(m.Target) + "." + m.Field,
        KrlIndex i => Describe(i.Target) + "[…]",
        _ => "the value",
    };
}
