using System.Text;

namespace Machina.Simulation;

public sealed partial class VirtualKukaController
{
    /// <summary>
    /// Does what the KRL driver's checks do before an action the robot cannot run (a target no axis position reaches, an axis
    /// beyond its software limit switch, a speed of 0): the failure report <c>&lt;F ID Code Text&gt;</c> instead of the
    /// acknowledgement, the quit message, then the program halts: nothing after it runs, the EthernetKRL channel stays open.
    /// Other refusals are logged and acknowledged as before.
    /// </summary>
    private protected override async Task<bool> StopsOnRefusalAsync(object request, int id, VirtualRefusalException refusal, CancellationToken token)
    {
        if (request is TwinAction)
        {
            return true; // the twin's driver sent its failure and halted
        }
        int? code = refusal.Kind switch
        {
            VirtualRefusalKind.Reach => KukaFailure.NotReachable,
            VirtualRefusalKind.JointLimits => KukaFailure.SoftwareLimit,
            VirtualRefusalKind.Speed => KukaFailure.NoSpeed,
            VirtualRefusalKind.Output => KukaFailure.NoSuchOutput,
            VirtualRefusalKind.OutputValue => KukaFailure.AnalogRange,
            _ => null,
        };
        if (code is not int failure)
        {
            return false;
        }
        Pendant("Machina: " + KukaFailure.Describe(failure));
        if (_heldAcknowledgement is byte[] held)
        {
            // The action before it ran: its acknowledgement goes out first.
            _heldAcknowledgement = null;
            await SendToClientAsync(held, token).ConfigureAwait(false);
        }
        await SendToClientAsync(Encoding.ASCII.GetBytes(KukaFailure.Message(id, failure)), token).ConfigureAwait(false);
        return true;
    }
}
