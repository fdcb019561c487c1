namespace Machina.Simulation;

public sealed partial class VirtualKukaController
{
    /// <summary>Sends the driver's acknowledgement of what its arm just ran (written at its EKI_Send of <c>R</c>), through the fault plan.</summary>
    private protected override void AfterExecuted(object request, int id, CancellationToken token) => AcknowledgeTwin((TwinAck)request, token);
}
