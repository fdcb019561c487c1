namespace Machina.Cli.Simulation;

/// <summary>
/// What <see cref="ControllerActivity"/> reads of a controller at each look: how far each of its logs has come and only the
/// entries after those already told (a "since" read copies nothing when nothing is new), the count of requests executed, a mark
/// that moves whenever the outputs may have, and the robot (read only when a line tells it).
/// </summary>
internal interface IControllerLook
{
    /// <summary>How many requests the controller has executed.</summary>
    int RequestsExecuted { get; }

    /// <summary>Changes whenever the outputs may have changed (compared by value; the robot is read again then).</summary>
    (object? Signals, long Writes) OutputsMark { get; }

    /// <summary>Adds the requests received after the first <paramref name="seen"/> to <paramref name="into"/>; returns the count for the next read.</summary>
    long RequestsSince(long seen, ICollection<string> into);

    /// <summary>Adds the ids executed after the first <paramref name="seen"/> to <paramref name="into"/>; returns the count for the next read.</summary>
    long ExecutedIdsSince(long seen, ICollection<int> into);

    /// <summary>Adds the pendant texts after the first <paramref name="seen"/> to <paramref name="into"/>; returns the count for the next read.</summary>
    long PendantSince(long seen, ICollection<string> into);

    /// <summary>Adds the errors after the first <paramref name="seen"/> to <paramref name="into"/>; returns the count for the next read.</summary>
    long ErrorsSince(long seen, ICollection<string> into);

    /// <summary>The robot now: where the tool and the joints are, and the outputs.</summary>
    ControllerRobot Robot();

    /// <summary>
    /// Set by the controller whenever something a look reads changes (the activity then sleeps until it is), or null for a
    /// controller that tells nothing (looked at every <see cref="ControllerActivity.Period"/>).
    /// </summary>
    Machina.Simulation.Twin.TwinChangeSignal? Changes { get; }
}

/// <summary>Where a controller's robot is, and its outputs, at one moment.</summary>
internal sealed record ControllerRobot(Vector Position, Joints Joints, IReadOnlyDictionary<string, bool> DigitalOutputs, IReadOnlyDictionary<string, double> AnalogOutputs);
