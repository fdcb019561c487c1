namespace Machina;

/// <summary>Where issued actions go when the robot is online: the release buffer of a connection.</summary>
internal interface IActionStream
{
    /// <summary>
    /// Takes an action that was just issued (already applied to the issue cursor and given its id). Called while the issue
    /// cursor is locked, so actions arrive in id order. <paramref name="issued"/> is the ActionIssued payload to raise, or
    /// null when nobody listens; the stream raises it before any later event about the same action.
    /// </summary>
    /// <param name="action">The action.</param>
    /// <param name="issued">The event's payload, or null.</param>
    /// <param name="frame">The action encoded for the wire (<see cref="Encode"/>), or null when the stream has no codec.</param>
    void Enqueue(RobotAction action, ActionIssuedArgs? issued, ActionFrame? frame);

    /// <summary>
    /// Releases what <see cref="Enqueue"/> took, as the connection allows. Called after the issue lock is released, never under
    /// it: the session's loop may run on the calling thread, and a failure it applies there must see every action of the issue.
    /// </summary>
    void ReleaseIssued();

    /// <summary>Why the controller's driver cannot run <paramref name="action"/>, or null; asked before the action changes anything.</summary>
    string? WhyCannotStream(RobotAction action);

    /// <summary>Why the driver cannot carry what <paramref name="action"/> sends from <paramref name="after"/>, the state it leads to, or null.</summary>
    string? WhyCannotSend(RobotAction action, RobotCursor after);

    /// <summary>
    /// Encodes <paramref name="action"/> from <paramref name="after"/>, the state it leads to, into <paramref name="frame"/> (null
    /// when the stream has no codec); returns why the driver cannot carry it, or null.
    /// </summary>
    string? Encode(RobotAction action, RobotCursor after, out ActionFrame? frame);
}
