namespace Machina;

public sealed partial class Robot
{
    /// <summary>A copy of the state the next issued action starts from (pose, settings, tools, the arm model), to try actions on.</summary>
    internal RobotCursor TrialCursor()
    {
        var trial = new RobotCursor();
        lock (_issueLock)
        {
            trial.CopyFrom(_issueCursor);
        }
        trial.Strict = _issueCursor.Strict;
        return trial;
    }

    /// <summary>
    /// Why issuing <paramref name="action"/> after the state of <paramref name="trial"/> would be refused (by the brand's online
    /// driver or the state), or null; the trial then holds the state after it, and its <c>LastIssues</c> the arm's problems.
    /// Nothing is issued or sent.
    /// </summary>
    internal string? TryOn(RobotCursor trial, RobotAction action)
    {
        if (_session?.WhyCannotStream(action) is string refused)
        {
            return refused;
        }
        return trial.TryApply(action) ?? _session?.WhyCannotSend(action, trial);
    }
}
