using System.Text;

namespace Machina.Simulation;

public sealed partial class VirtualAbbController
{
    private string? _failureReport;

    /// <summary>
    /// Stops the driver program on a request the robot cannot run, as the RAPID modules do (docs/protocol-abb.md, "Failures"):
    /// nothing is acknowledged and nothing after it runs; the links stay open, as they do when a RAPID program stops.
    /// A move with a speed of 0 is the driver's own check: it writes <c>$26 id 1;</c> on the driver link before stopping. A target
    /// out of reach or joints beyond their limits stop the motion task with event 50050; the monitor task's error trap writes
    /// <c>$26 id 50050;</c> on the monitor link. Other refusals are logged and acknowledged as before.
    /// </summary>
    private protected override async Task<bool> StopsOnRefusalAsync(object request, int id, VirtualRefusalException refusal, CancellationToken token)
    {
        switch (refusal.Kind)
        {
            case VirtualRefusalKind.Speed:
                Pendant($"Machina: request {id} failed: {AbbFailure.Describe(AbbFailure.NoSpeed)}");
                await SendToClientAsync(Encoding.ASCII.GetBytes(AbbFailure.Message(id, AbbFailure.NoSpeed)), token).ConfigureAwait(false);
                return true;
            case VirtualRefusalKind.Reach or VirtualRefusalKind.JointLimits:
                Pendant($"50050 Position outside reach: {refusal.Message}");
                lock (Gate)
                {
                    _failureReport = AbbFailure.Message(id, AbbFailure.OutsideReach);
                }
                return true;
            default:
                return false;
        }
    }

    /// <summary>The failure report the monitor sends next (once), or null.</summary>
    private string? TakeFailureReport()
    {
        lock (Gate)
        {
            string? report = _failureReport;
            _failureReport = null;
            return report;
        }
    }
}
