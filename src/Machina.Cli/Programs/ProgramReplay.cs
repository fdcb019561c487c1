namespace Machina.Cli.Programs;

/// <summary>
/// Applies a program's actions one by one to a robot state, as a robot would when they are issued: with a model every motion is
/// checked (reach, joint limits, singularities, flips, joint speeds). Gives each action the id a robot would (1, 2, 3…).
/// </summary>
internal sealed class ProgramReplay
{
    private string? _lastWarning;

    /// <summary>A replay from Machina's initial state, with the arm model <paramref name="model"/> (or none).</summary>
    internal ProgramReplay(RobotModel? model)
    {
        Cursor = new RobotCursor { Model = model, Strict = false };
        Cursor.Warn = (_, message) => _lastWarning = message;
    }

    /// <summary>The state after the last applied action.</summary>
    internal RobotCursor Cursor { get; }

    /// <summary>How many actions were applied.</summary>
    internal int Count { get; private set; }

    /// <summary>True for the actions that move the robot.</summary>
    internal static bool IsMotion(RobotAction action) =>
        action is ActionTranslation or ActionRotation or ActionTransformation or ActionAxes or ActionArcMotion;

    /// <summary>
    /// Applies the action. Returns null when it was applied, else why it cannot be (nothing changed). <paramref name="problems"/>
    /// receives what was applied but deserves a look: kinematic issues and surprising settings, in plain words.
    /// </summary>
    internal string? Apply(RobotAction action, List<string> problems)
    {
        problems.Clear();
        _lastWarning = null;
        string? refusal = Cursor.TryApply(action);
        if (refusal is not null)
        {
            return refusal;
        }
        action.Id = ++Count;
        if (_lastWarning is not null)
        {
            problems.Add(_lastWarning);
        }
        foreach (KinematicIssue issue in Cursor.LastIssues)
        {
            problems.Add(issue.ToString());
        }
        return null;
    }
}
