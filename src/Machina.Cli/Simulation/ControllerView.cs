namespace Machina.Cli.Simulation;

/// <summary>
/// What a virtual controller shows of itself at one moment, read from its public inspection members: the requests it parsed
/// (one per instruction, however the host wrote them), what it executed, its pendant, its errors, the robot and its outputs.
/// </summary>
internal sealed record ControllerView(
    int RequestsReceived, IReadOnlyList<string> Requests, int RequestsExecuted, IReadOnlyList<int> ExecutedIds,
    IReadOnlyList<string> Pendant, IReadOnlyList<string> Errors, Vector Position, Joints Joints,
    IReadOnlyDictionary<string, bool> DigitalOutputs, IReadOnlyDictionary<string, double> AnalogOutputs)
{
    /// <summary>Reads the view of a controller of the simulation library.</summary>
    internal static ControllerView Of(Machina.Simulation.RunningVirtualController controller)
    {
        Machina.Simulation.VirtualRobotState state = controller.State;
        return new ControllerView(controller.RequestsReceived, controller.ReceivedRequests, controller.RequestsExecuted, controller.ExecutedIds,
            controller.PendantMessages, controller.Errors, state.Position, state.Joints, state.DigitalOutputs, state.AnalogOutputs);
    }
}
