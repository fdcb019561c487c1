namespace Machina.Simulation;

public sealed partial class VirtualKukaController
{
    /// <summary>
    /// An action the KRL driver refused (a target no axis position reaches, an axis beyond its software limit switch, a speed of
    /// 0, an output that does not exist): the driver sent its failure report <c>&lt;F ID Code Text&gt;</c> instead of the
    /// acknowledgement and halted, so nothing after it runs; the EthernetKRL channel stays open.
    /// </summary>
    private protected override Task<bool> StopsOnRefusalAsync(object request, int id, VirtualRefusalException refusal, CancellationToken token) =>
        Task.FromResult(true);
}
