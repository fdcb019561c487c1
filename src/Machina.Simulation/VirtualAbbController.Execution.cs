namespace Machina.Simulation;

public sealed partial class VirtualAbbController
{
    /// <summary>Sends the driver's acknowledgement of what its arm just ran (the RAPID driver wrote it at its SocketSend).</summary>
    private protected override void AfterExecuted(object request, int id, CancellationToken token) =>
        AcknowledgeTwin((TwinRequest)request, token);

    /// <summary>The robot as the RAPID twin's arm has it now (the options' starting state until the twin is made).</summary>
    private protected override VirtualAbbState Observe(VirtualAbbState kept) => Twin is { } twin ? TwinState(twin, kept) : kept;
}
