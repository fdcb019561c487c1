namespace Machina;

public sealed partial class Robot
{
    private readonly List<ProgramWarning> _warnings = [];

    /// <summary>
    /// A robot with a name, a brand and the model of its arm, e.g. <c>Robot.Create("Bot", "UR", "UR5e")</c>. With a model the robot
    /// knows joints and pose together and checks every motion (see <see cref="SetModel(RobotModel?)"/>).
    /// </summary>
    /// <exception cref="ArgumentException">Unknown brand or model, or the model is of another brand.</exception>
    public static Robot Create(string name, string brand, string model)
    {
        Robot robot = Create(name, brand);
        robot.SetModel(model);
        return robot;
    }

    /// <summary>A robot with a name, a brand and the model of its arm (built-in or your own <see cref="RobotModel"/>).</summary>
    /// <exception cref="ArgumentException">The model is of another brand.</exception>
    public static Robot Create(string name, RobotType brand, RobotModel model)
    {
        ArgumentNullException.ThrowIfNull(model);
        Robot robot = Create(name, brand);
        robot.SetModel(model);
        return robot;
    }

    /// <summary>Every built-in robot model (the same list as <see cref="RobotModels.All"/>).</summary>
    public static IReadOnlyList<RobotModel> Models => RobotModels.All;

    /// <summary>The model of this robot's arm, or null when none was chosen (then Machina does no kinematics).</summary>
    public RobotModel? Model
    {
        get
        {
            lock (_issueLock)
            {
                return _issueCursor.Model;
            }
        }
    }

    /// <summary>
    /// How many motions this robot's cursors solved (the issue cursor, and online the release and execution cursors); a solution one
    /// cursor shares with the others counts once. For tests and benchmarks: solves per action.
    /// </summary>
    internal int KinematicSolves()
    {
        int issued;
        lock (_issueLock)
        {
            issued = _issueCursor.Solves;
        }
        // Asked after the issue lock is released: nobody asks the session's loop a question while holding it.
        return issued + (_session?.Solves() ?? 0);
    }

    /// <summary>Chooses the built-in model with this name (e.g. "IRB 120", "UR5e", "KR 6 R700 sixx"); see <see cref="SetModel(RobotModel?)"/>.</summary>
    /// <exception cref="ArgumentException">There is no such model (the message suggests close names) or it is of another brand.</exception>
    public void SetModel(string model)
    {
        ArgumentNullException.ThrowIfNull(model);
        SetModel(Arg.Renamed("name", nameof(model), model, static m => RobotModels.Get(m)));
    }

    /// <summary>
    /// Chooses the model of this robot's arm (null: none). Allowed only while the robot's position and joints are still unknown,
    /// i.e. before the first motion, so the whole program is computed with one model.
    /// </summary>
    /// <exception cref="ArgumentException">The model is of another brand than this robot.</exception>
    /// <exception cref="InvalidOperationException">A motion was already issued, or the robot is connected (choose the model before connecting).</exception>
    public void SetModel(RobotModel? model)
    {
        if (model is not null)
        {
            CheckModelBrand(model);
        }
        lock (_issueLock)
        {
            if (_session is not null)
            {
                throw new InvalidOperationException("The robot model must be chosen before connecting to the controller (the stream keeps its own copy of the state).");
            }
            if (_issueCursor.Position is not null || _issueCursor.Axes is not null)
            {
                throw new InvalidOperationException(
                    "The robot model can only be chosen before the first motion (while the position and joints are unknown); " +
                    "create the robot with its model, or call SetModel before any MoveTo, TransformTo or AxesTo.");
            }
            _issueCursor.Model = model;
        }
    }

    private void CheckModelBrand(RobotModel model)
    {
        BrandDefinition definition = BrandRegistry.For(Brand);
        if (definition.Kind == BrandKind.Printer)
        {
            throw new ArgumentException($"A {Brand} robot is a 3D printer; arm models such as {model} do not apply to it.", nameof(model));
        }
        string? brand = definition.ModelBrand;
        if (brand is not null && !string.Equals(brand, model.Brand, StringComparison.Ordinal))
        {
            throw new ArgumentException($"The model {model} is a {model.Brand} arm, but this robot's brand is {Brand}.", nameof(model));
        }
    }

    /// <summary>
    /// Strict mode (only with a model): a motion that fails any kinematic check (unreachable, joint limit, singularity, configuration
    /// flip, joint speed) is refused with an <see cref="ActionRefusedException"/> instead of being issued with a warning.
    /// </summary>
    public void StrictMode(bool strict)
    {
        lock (_issueLock)
        {
            _issueCursor.Strict = strict;
        }
    }

    /// <summary>True when strict mode is on (see <see cref="StrictMode"/>).</summary>
    public bool IsStrict
    {
        get
        {
            lock (_issueLock)
            {
                return _issueCursor.Strict;
            }
        }
    }

    /// <summary>The kinematic warnings of the actions issued so far, in order, each with the action's id and the check's kind.</summary>
    public IReadOnlyList<ProgramWarning> GetWarnings()
    {
        lock (_issueLock)
        {
            return [.. _warnings];
        }
    }

    /// <summary>Forgets the warnings collected so far.</summary>
    public void ClearWarnings()
    {
        lock (_issueLock)
        {
            _warnings.Clear();
        }
    }

    /// <summary>Keeps and logs the kinematic issues of an action just issued (called under the issue lock).</summary>
    private void RecordIssues(RobotAction action, IReadOnlyList<KinematicIssue> issues)
    {
        foreach (KinematicIssue issue in issues)
        {
            var warning = new ProgramWarning(action.Id, action.ToInstruction(), issue.ToString()) { Kind = issue.Kind };
            _warnings.Add(warning);
            LogLocked(LogLevel.WARNING, warning.ToString());
        }
    }
}
