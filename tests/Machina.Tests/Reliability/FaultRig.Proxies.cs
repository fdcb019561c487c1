using System.Net;
using Machina.Simulation;
using Machina.Tests.Support;

namespace Machina.Tests.Reliability;

internal sealed partial class FaultRig
{
    /// <summary>The controller's consecutive ports a <see cref="FaultProxy"/> mirrors: driver and monitor (ABB, KUKA), or script, RTDE and dashboard (UR).</summary>
    public int[] ProxiedPorts => Controller switch
    {
        VirtualUrController ur => [ur.Port, ur.RtdePort, ur.DashboardPort],
        _ => [Port, Port + 1],
    };

    /// <summary>
    /// A UR controller (instant execution, no model) whose driver program calls the host back through <paramref name="back"/>:
    /// its <c>OutboundRoute</c> points the proxy's first channel at the call-back port the host chose and connects there.
    /// </summary>
    public static async Task<FaultRig> StartUrThroughAsync(FaultProxy back, int logCapacity = 10_000)
    {
        var c = new VirtualUrController(new VirtualUrControllerOptions
        {
            InstantExecution = true, Model = null, RequestLogCapacity = logCapacity,
            OutboundRoute = to =>
            {
                back.Retarget(0, to.Port); // the host's call-back port, chosen when it connects
                return new DnsEndPoint("127.0.0.1", back.Port);
            },
        });
        await c.StartAsync();
        return Of("UR", c.Port, c);
    }
}
