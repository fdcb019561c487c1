namespace Machina;

/// <summary>
/// The comment lines every program writer puts where an action gives no code: its description (human-readable programs),
/// "not applicable to this device", and an error with its reason. One wording for every language; each brings its
/// comment marker (<c>;</c>, <c>!</c>, <c>#</c>) and the escaping its comments need.
/// </summary>
internal sealed class ProgramNotes(string marker, Func<string, string> escape)
{
    /// <summary>The notes of KRL and G-code: <c>;</c> comments on one line.</summary>
    internal static readonly ProgramNotes Semicolon = new(";", ProgramText.OneLine);

    /// <summary>The note of an action with no code here, in a human-readable program: <c>; [Wait 1000 ms]</c>.</summary>
    internal string Description(RobotAction action) => marker + " [" + escape(action.Describe()) + "]";

    /// <summary>The note of an action this device cannot do: <c>; ACTION "…" NOT APPLICABLE TO THIS DEVICE</c>.</summary>
    internal string NotApplicable(RobotAction action) => marker + " ACTION \"" + escape(action.Describe()) + "\" NOT APPLICABLE TO THIS DEVICE";

    /// <summary>The note of an action that could not be written: <c>; ERROR on "…": reason</c>.</summary>
    internal string Error(RobotAction action, string reason) => marker + " ERROR on \"" + escape(action.Describe()) + "\": " + reason;
}
