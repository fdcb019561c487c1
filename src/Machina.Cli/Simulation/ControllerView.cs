namespace Machina.Cli.Simulation;

/// <summary>
/// What a virtual controller shows of itself at one moment, its logs copied whole: the requests it parsed (one per instruction,
/// however the host wrote them), what it executed, its pendant, its errors, the robot and its outputs. A scripted look
/// (<see cref="ControllerViewLook"/>); a running controller is read through <see cref="LiveControllerLook"/>, which copies only what is new.
/// </summary>
internal sealed record ControllerView(
    int RequestsReceived, IReadOnlyList<string> Requests, int RequestsExecuted, IReadOnlyList<int> ExecutedIds,
    IReadOnlyList<string> Pendant, IReadOnlyList<string> Errors, Vector Position, Joints Joints,
    IReadOnlyDictionary<string, bool> DigitalOutputs, IReadOnlyDictionary<string, double> AnalogOutputs);
