namespace Machina;

/// <summary>
/// What an <see cref="OnlineSession"/> may ask of its robot, and nothing more: who it is, where to log, whether anybody listens
/// to an event, how to raise one, and the issue cursor under the robot's issue lock.
/// </summary>
internal interface IOnlineHost
{
    /// <summary>The robot's name, for messages.</summary>
    string Name { get; }

    /// <summary>The robot's brand, for messages.</summary>
    RobotType Brand { get; }

    /// <summary>The robot's log.</summary>
    RobotLogger Logger { get; }

    /// <summary>True when the event carried by <paramref name="kind"/> has subscribers (so its payload is worth building).</summary>
    bool IsListening(OnlineEvent kind);

    /// <summary>Delivers an online event to its subscribers; called one at a time by the session's event loop; never throws.</summary>
    void Raise(MachinaEventArgs args);

    /// <summary>
    /// Runs <paramref name="change"/> on the issue cursor while holding the robot's issue lock, so that no action is issued
    /// meanwhile (the session calls it from its loop). Returns the log lines the change wrote, for the session to write on its
    /// event pump (log sinks never run under the lock), or null.
    /// </summary>
    IReadOnlyList<(LogLevel Level, string Message)>? WithIssueCursor(Action<RobotCursor> change);
}

/// <summary>The online events a session raises.</summary>
internal enum OnlineEvent
{
    /// <summary><c>Robot.ActionReleased</c>.</summary>
    Released,

    /// <summary><c>Robot.ActionExecuted</c>.</summary>
    Executed,

    /// <summary><c>Robot.MotionUpdate</c>.</summary>
    Motion,

    /// <summary><c>Robot.ConnectionLost</c>.</summary>
    ConnectionLost,

    /// <summary><c>Robot.ControllerStopped</c> and <c>Robot.ControllerResumed</c>.</summary>
    StopChanged,

    /// <summary><c>Robot.ActionFailed</c>.</summary>
    Failed,
}
