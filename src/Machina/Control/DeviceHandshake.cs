namespace Machina;

/// <summary>What a controller reports when a connection opens: its driver version and where the robot is.</summary>
/// <param name="Version">Driver version text, such as "1.4.2".</param>
/// <param name="Position">Flange position in mm, or null when not reported.</param>
/// <param name="Rotation">Flange orientation, or null when not reported.</param>
/// <param name="Axes">Joint angles in degrees, or null when not reported.</param>
/// <param name="ExternalAxes">External axis values, or null when the robot has none.</param>
/// <param name="Progress">Where the controller is in the request stream, or null when its driver does not say.</param>
internal sealed record DeviceHandshake(string Version, Vector? Position, Rotation? Rotation, Joints? Axes, ExternalAxes? ExternalAxes, DeviceProgress? Progress = null)
{
    /// <summary>The arm as the controller names it (UR dashboard, ABB robot type, KUKA <c>$MODEL_NAME[]</c>), or null when it did not say.</summary>
    public string? ModelName { get; init; }

    /// <summary>The catalogue model that <see cref="ModelName"/> names, or null when there is none (or no name).</summary>
    public RobotModel? Model { get; init; }
}

/// <summary>
/// The wire ids of the last request the controller executed and of the last one it received (0 when none): requests in
/// between are still in its buffer and will be executed and acknowledged. Lets a reconnecting host send nothing twice.
/// </summary>
internal readonly record struct DeviceProgress(int LastExecutedId, int LastReceivedId)
{
    /// <summary>True when the controller still holds requests it has not executed.</summary>
    public bool IsBusy => LastReceivedId != LastExecutedId;

    /// <summary>True for a driver that has not executed or received anything since it started.</summary>
    public bool IsFresh => LastExecutedId == 0 && LastReceivedId == 0;
}

/// <summary>One live pose report from the controller (ABB monitor <c>$24</c>).</summary>
internal readonly record struct MotionSample(Vector Position, Rotation Rotation, Joints Axes, ExternalAxes? ExternalAxes);
