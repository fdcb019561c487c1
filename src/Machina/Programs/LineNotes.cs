namespace Machina;

/// <summary>
/// The lines a program writer puts where an action gives no code of its own, one set for every writer: the action's description in a
/// human-readable program (<see cref="NoCode"/>), and, with a warning, "not applicable to this device" or an error with its reason
/// written as the action's line (<see cref="NotApplicable"/>, <see cref="Error"/>). The wording is <see cref="ProgramNotes"/>'.
/// </summary>
/// <param name="job">The compile, which collects the warnings and says whether the program is human-readable.</param>
/// <param name="notes">The language's comment marker and escaping.</param>
/// <param name="indent">What goes before a description line.</param>
/// <param name="sink">Where the writer's lines go now (a writer that opens its file later gives it then).</param>
/// <param name="code">Writes a note as the action's line, as the writer writes code (its description comment included); null for a writer that writes no such notes.</param>
internal sealed class LineNotes(CompileJob job, ProgramNotes notes, string indent, Func<LineSink> sink, Action<string, RobotAction>? code = null)
{
    private readonly bool _human = job.Options.HumanComments;

    /// <summary>An action with no code here: its description, in a human-readable program only.</summary>
    internal void NoCode(RobotAction action)
    {
        if (_human)
        {
            sink().Add(indent + notes.Description(action));
        }
    }

    /// <summary>An action this device cannot do: a warning, and the note as its line.</summary>
    internal void NotApplicable(RobotAction action, string reason)
    {
        job.Warn(action, reason);
        Code(notes.NotApplicable(action), action);
    }

    /// <summary>An action that could not be written: a warning, and the error with its reason as its line.</summary>
    internal void Error(RobotAction action, string reason)
    {
        job.Warn(action, reason);
        Code(notes.Error(action, reason), action);
    }

    private void Code(string line, RobotAction action) =>
        (code ?? throw new InvalidOperationException("This writer writes no notes as code."))(line, action);
}
