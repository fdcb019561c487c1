using Machina.Simulation;
using static Machina.Tests.Online.KukaTestSupport;
using static Machina.Tests.Online.OnlineTestSupport;

namespace Machina.Tests.Online;

/// <summary>
/// The reconnect contract against the virtual KUKA controller, whose KRL driver reports its state and progress (<c>S</c> with
/// Executed and Received) on every connection; and what only KUKA has: actions held on the host while the ring is full.
/// </summary>
public class KukaReconnectTests : ReconnectContract<VirtualKukaController, VirtualKukaState>
{
    protected override string Brand => "KUKA";

    /// <summary>
    /// The contract pauses execution (<c>StopAnswering</c>) while the driver goes on serving connections and reporting progress.
    /// The KRL driver serves a connection only between two actions, so a driver held at an acknowledgement cannot: the contract
    /// runs on the imitation of the driver; the KRL twin's reconnection is covered by the fault matrix (Drop, Truncate, restarts).
    /// </summary>
    protected override Task<VirtualKukaController> StartAsync() => StartKukaAsync(new VirtualKukaControllerOptions { InstantExecution = true, RunsKrl = false });

    protected override Task<VirtualKukaController> StartWithoutProgressAsync() =>
        StartKukaAsync(new VirtualKukaControllerOptions { InstantExecution = true, DriverVersion = new Version(1, 0), RunsKrl = false });

    protected override async Task<Robot> ConnectAsync(VirtualKukaController controller, Action<Robot> configure) =>
        (await ConnectKukaAsync(controller, configure)).Bot;

    protected override int PortOf(VirtualKukaController controller) => controller.Port;

    protected override IEnumerable<int> ReceivedIds(VirtualKukaController controller) => KukaTestSupport.ReceivedIds(controller);

    [Fact]
    public async Task Reconnect_ActionsHeldOnTheHostForAFullRing_SentAfterTheOnesTheControllerHolds()
    {
        // Paused execution while reconnecting: the imitation (see StartAsync).
        await using var controller = await StartAsync();
        var (bot, executed, lost) = await ConnectWatchedAsync(controller, b => { b.BlockSize = 150; b.PendingCount = 150; });
        controller.StopAnswering();
        bot.MoveTo(Start.X, Start.Y, Start.Z);
        for (int i = 0; i < 149; i++)
        {
            bot.Move(0, i % 2 == 0 ? 10 : -10, 0);
        }
        await EventuallyAsync(() => controller.BufferedRequestCount == KukaProtocol.Capacity, "the ring to fill");
        controller.CloseConnectionAfter(3);
        controller.ResumeAnswering(3);
        await lost.Task.WaitAsync(Limit);

        // 97 actions wait in the ring, 50 never left the host.
        await bot.ConnectAsync("127.0.0.1", controller.Port).WaitAsync(Limit);
        controller.ResumeAnswering();
        await bot.WaitForCompletionAsync().WaitAsync(Limit);
        await bot.FlushEventsAsync().WaitAsync(Limit);

        Assert.Equal(Enumerable.Range(1, 150), executed);
        Assert.Equal(Enumerable.Range(1, 150), ReceivedIds(controller));
        Assert.Equal(150, controller.RequestsExecuted);
        Assert.Equal(new Vector(400, 10, 400), controller.State.Position);
        Assert.Empty(controller.Errors);
        await bot.DisconnectAsync();
    }
}
