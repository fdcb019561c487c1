using System.Globalization;
using Machina.Simulation;
using Machina.Tests.Support;
using static Machina.Tests.Online.OnlineTestSupport;

namespace Machina.Tests.Online;

/// <summary>The reconnect contract against the virtual ABB controller, whose driver reports its progress with <c>$25</c>.</summary>
public class AbbReconnectTests : ReconnectContract<VirtualAbbController, VirtualAbbState>
{
    protected override string Brand => "ABB";

    protected override Task<VirtualAbbController> StartAsync() => StartControllerAsync(new VirtualAbbControllerOptions { InstantExecution = true });

    /// <summary>
    /// The RAPID driver accepts a client only once it ran everything it read: while it is held at the owner's first acknowledgement,
    /// a stranger waits in the listen queue and never gets a handshake (its robot's clock, moved here, ends the wait).
    /// </summary>
    protected override async Task ConnectStrangerAsync(VirtualAbbController controller)
    {
        var clock = new ManualClock();
        var stranger = Robot.Create("Stranger", Brand);
        stranger.ControlMode("online");
        stranger.Time = clock;
        stranger.ConnectTimeout = TimeSpan.FromSeconds(1);
        Task connecting = stranger.ConnectAsync("127.0.0.1", controller.Port);
        // The handshake's timer; on Linux a peer that answers at once is connected without a deadline timer of its own.
        await EventuallyAsync(() => clock.TimersCreated == (OperatingSystem.IsLinux() ? 1 : 2), "the stranger to wait for the handshake (after the TCP connect)");
        clock.Advance(TimeSpan.FromSeconds(1));
        var refused = await Assert.ThrowsAsync<RobotConnectionException>(() => connecting.WaitAsync(Limit));
        Assert.Contains("did not send its handshake within 1 s", refused.Message, StringComparison.Ordinal);
        Assert.False(stranger.IsConnected);
        Assert.Equal(1, controller.ConnectionCount);
    }

    /// <summary>
    /// The driver answers only once it ran everything it read, so the controller answers first: it runs what it holds while nobody
    /// listens (their acknowledgements lost), then reports them executed in the handshake; the robot sends only the rest.
    /// </summary>
    protected override async Task ReconnectWhileHeldAsync(Robot bot, VirtualAbbController controller)
    {
        Task connecting = bot.ConnectAsync("127.0.0.1", controller.Port);
        controller.ResumeAnswering();
        await connecting.WaitAsync(Limit);
        Assert.Equal(2, controller.ConnectionCount);
    }

    /// <summary>
    /// The driver answers the owner only once it ran the two actions, so the controller answers first: it runs them while nobody
    /// listens, drops the stranger who left the listen queue, and reports both executed in the owner's handshake.
    /// </summary>
    protected override async Task ReconnectOwnerAndResumeAsync(Robot owner, VirtualAbbController controller)
    {
        Task connecting = owner.ConnectAsync("127.0.0.1", controller.Port);
        controller.ResumeAnswering();
        await connecting.WaitAsync(Limit);
    }

    protected override Task<Robot> ConnectAsync(VirtualAbbController controller, Action<Robot> configure) =>
        OnlineTestSupport.ConnectAsync(controller, configure);

    protected override int PortOf(VirtualAbbController controller) => controller.Port;

    /// <summary>Requests are logged as "@id …".</summary>
    protected override IEnumerable<int> ReceivedIds(VirtualAbbController controller) =>
        controller.ReceivedRequests.Select(r => int.Parse(r[1..r.IndexOf(' ')], CultureInfo.InvariantCulture));
}
