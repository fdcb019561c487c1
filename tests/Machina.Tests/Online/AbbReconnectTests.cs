using System.Globalization;
using Machina.Simulation;
using static Machina.Tests.Online.OnlineTestSupport;

namespace Machina.Tests.Online;

/// <summary>The reconnect contract against the virtual ABB controller, whose driver reports its progress with <c>$25</c>.</summary>
public class AbbReconnectTests : ReconnectContract<VirtualAbbController, VirtualAbbState>
{
    protected override string Brand => "ABB";

    // The imitation (RunsRapid = false): the contract pauses the controller and expects it to hold every released request;
    // the RAPID driver reads only when it has run what it read (80 characters at a time), and its version is the module's.
    protected override Task<VirtualAbbController> StartAsync() => StartControllerAsync(new VirtualAbbControllerOptions { InstantExecution = true, RunsRapid = false });

    protected override Task<VirtualAbbController> StartWithoutProgressAsync() =>
        StartControllerAsync(new VirtualAbbControllerOptions { InstantExecution = true, DriverVersion = new Version(1, 5, 0), Model = null, RunsRapid = false });

    protected override Task<Robot> ConnectAsync(VirtualAbbController controller, Action<Robot> configure) =>
        OnlineTestSupport.ConnectAsync(controller, configure);

    protected override int PortOf(VirtualAbbController controller) => controller.Port;

    /// <summary>Requests are logged as "@id …".</summary>
    protected override IEnumerable<int> ReceivedIds(VirtualAbbController controller) =>
        controller.ReceivedRequests.Select(r => int.Parse(r[1..r.IndexOf(' ')], CultureInfo.InvariantCulture));
}
