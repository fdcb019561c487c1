using Machina.Simulation;

namespace Machina.Cli.Simulation;

/// <summary>A running virtual controller as <see cref="ControllerActivity"/> reads it: its inspection members' "since" reads, one object for every look.</summary>
internal sealed class LiveControllerLook(RunningVirtualController controller) : IControllerLook
{
    /// <inheritdoc/>
    public int RequestsExecuted => controller.RequestsExecuted;

    /// <inheritdoc/>
    public (object? Signals, long Writes) OutputsMark => controller.OutputsMark;

    /// <inheritdoc/>
    public long RequestsSince(long seen, ICollection<string> into) => controller.ReceivedRequestsSince(seen, into);

    /// <inheritdoc/>
    public long ExecutedIdsSince(long seen, ICollection<int> into) => controller.ExecutedIdsSince(seen, into);

    /// <inheritdoc/>
    public long PendantSince(long seen, ICollection<string> into) => controller.PendantMessagesSince(seen, into);

    /// <inheritdoc/>
    public long ErrorsSince(long seen, ICollection<string> into) => controller.ErrorsSince(seen, into);

    /// <inheritdoc/>
    public Machina.Simulation.Twin.TwinChangeSignal? Changes => controller.Changes;

    /// <inheritdoc/>
    public ControllerRobot Robot()
    {
        VirtualRobotState state = controller.State;
        return new ControllerRobot(state.Position, state.Joints, state.DigitalOutputs, state.AnalogOutputs);
    }
}
