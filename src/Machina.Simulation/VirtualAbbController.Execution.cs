namespace Machina.Simulation;

public sealed partial class VirtualAbbController
{
    /// <summary>Sends the driver's acknowledgement of what its arm just ran (the RAPID driver wrote it at its SocketSend).</summary>
    private protected override async Task<bool> AfterExecutedAsync(object request, int id, CancellationToken token) =>
        await AcknowledgeTwinAsync((TwinRequest)request, token).ConfigureAwait(false);

    /// <summary>The twin's arm already ran the request: the state it reports is where the arm is, and it takes no more time.</summary>
    private protected override VirtualStep Plan(VirtualAbbState s, object request) =>
        new(Twin is { } twin ? TwinState(twin, s) : s, 0);

    /// <summary>The robot as the RAPID twin's arm has it now (the options' starting state until the twin is made).</summary>
    private protected override VirtualAbbState Observe(VirtualAbbState kept) => Twin is { } twin ? TwinState(twin, kept) : kept;
}
