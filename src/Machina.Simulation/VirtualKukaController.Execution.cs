namespace Machina.Simulation;

public sealed partial class VirtualKukaController
{
    private protected override async Task<bool> AfterExecutedAsync(object request, int id, CancellationToken token)
    {
        // Planned means acknowledged by the driver already; a stopped action's failure went out instead, nothing more is sent.
        TwinAck ack = await ((TwinAction)request).Acknowledged.Task.ConfigureAwait(false);
        return ack.Stopped || await AcknowledgeTwinAsync(ack, token).ConfigureAwait(false);
    }

    /// <summary>The state after an action the twin's driver ran (it waits for the driver's acknowledgement or failure); no time of its own.</summary>
    private protected override VirtualStep Plan(VirtualKukaState s, object request)
    {
        AwaitTwinAction((TwinAction)request, _twinToken);
        // The twin's driver ran it on its arm already: the state the controller keeps is the twin's now.
        return new(Twin is { } twin ? TwinState(twin, s) : s, 0);
    }
}
