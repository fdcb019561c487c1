namespace Machina;

/// <summary>Where issued actions go when the robot is online: the release buffer of a connection.</summary>
internal interface IActionStream
{
    /// <summary>Takes an action that was just issued (already applied to the issue cursor and given its id).</summary>
    void Enqueue(RobotAction action);
}
