namespace Machina;

/// <summary>Saves (<c>PushSettings</c>) or restores (<c>PopSettings</c>) speed, acceleration, precision, motion type, reference frame and extrusion rate.</summary>
public sealed record ActionPushPop : RobotAction
{
    /// <summary>Creates a push (true) or pop (false) action.</summary>
    public ActionPushPop(bool push) => Push = push;

    /// <summary>True to save the settings, false to restore the last saved ones.</summary>
    public bool Push { get; }

    /// <inheritdoc/>
    public override ActionType Type => ActionType.PushPop;

    /// <inheritdoc/>
    public override string ToInstruction() => Push ? "PushSettings();" : "PopSettings();";

    /// <inheritdoc/>
    public override string Describe() => Push ? "Push settings to buffer" : "Pop settings";
}
