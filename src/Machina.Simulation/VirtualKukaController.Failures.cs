namespace Machina.Simulation;

public sealed partial class VirtualKukaController
{
    /// <summary>The failure code of the driver's stop (Robot.Stop): the action under way ended part-way, the driver keeps serving.</summary>
    private const int StoppedCode = 7;

    /// <summary>
    /// An action the KRL driver refused (a target no axis position reaches, an axis beyond its software limit switch, a speed of
    /// 0, an output that does not exist): the driver sent its failure report <c>&lt;F ID Code Text&gt;</c> instead of the
    /// acknowledgement and halted, so nothing after it runs; the EthernetKRL channel stays open. A stop (code 7) is not a halt:
    /// the driver dropped the rest and serves the next connection, so the controller goes on too.
    /// </summary>
    private protected override Task<bool> StopsOnRefusalAsync(object request, int id, VirtualRefusalException refusal, CancellationToken token) =>
        Task.FromResult(!IsStopped(request));

    /// <summary>The stopped action did not run to its end: it is not logged as executed.</summary>
    private protected override bool FailsProgram(object request, string reason) => IsStopped(request);

    private static bool IsStopped(object request) =>
        request is TwinAction { Acknowledged.Task: { IsCompletedSuccessfully: true, Result.Stopped: true } };
}
