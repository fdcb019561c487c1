using System.Collections.Concurrent;
using Machina.Simulation;
using static Machina.Tests.Online.KukaTestSupport;
using static Machina.Tests.Online.OnlineTestSupport;

namespace Machina.Tests.Online;

/// <summary>
/// A KUKA connection lost mid-program and opened again to the same controller: the KRL driver reports its state and progress
/// (<c>S</c> with Executed and Received) on every connection, so every action runs exactly once and keeps its target.
/// </summary>
public class KukaReconnectTests
{
    private static readonly Vector Start = new(400, 0, 400);

    [Fact]
    public async Task Reconnect_ControllerStillHoldsActions_WaitsForThemAndSendsOnlyTheRest()
    {
        await using var controller = await StartKukaAsync();
        var (bot, executed, lost) = await ConnectKukaAsync(controller);
        int released = await IssueTwentyWhilePausedAsync(bot, controller);
        controller.CloseConnectionAfter(3);
        controller.ResumeAnswering(3);

        await lost.Task.WaitAsync(Limit);
        await bot.FlushEventsAsync().WaitAsync(Limit);
        Assert.Equal([1, 2, 3], executed);
        Assert.Equal((3, released - 3), (controller.RequestsExecuted, controller.BufferedRequestCount));

        await bot.ConnectAsync("127.0.0.1", controller.Port).WaitAsync(Limit);
        Assert.Equal(2, controller.ConnectionCount);
        Assert.Equal(Enumerable.Range(4, 17), bot.GetPendingActions().Select(a => a.Id));
        controller.ResumeAnswering();
        await bot.WaitForCompletionAsync().WaitAsync(Limit);
        await bot.FlushEventsAsync().WaitAsync(Limit);

        AssertEachOnce(controller, executed);
        await bot.DisconnectAsync();
    }

    [Fact]
    public async Task Reconnect_ActionsHeldOnTheHostForAFullRing_SentAfterTheOnesTheControllerHolds()
    {
        await using var controller = await StartKukaAsync();
        var (bot, executed, lost) = await ConnectKukaAsync(controller, b => { b.BlockSize = 150; b.PendingCount = 150; });
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

    [Fact]
    public async Task Reconnect_ControllerRanTheRestWhileDisconnected_CountsThemExecutedAndKeepsTargets()
    {
        await using var controller = await StartKukaAsync();
        var (bot, executed, _) = await RunWhileDisconnectedAndReconnectAsync(controller);

        // The original's driver sent its state once per program run: a reconnection timed out.
        AssertEachOnce(controller, executed);
        await bot.DisconnectAsync();
    }

    [Fact]
    public async Task Reconnect_DriverWithoutProgress_SendsUnconfirmedAgainFromTheReportedPose()
    {
        await using var controller = await StartKukaAsync(new VirtualKukaControllerOptions { InstantExecution = true, DriverVersion = new Version(1, 0) });
        var (bot, executed, released) = await RunWhileDisconnectedAndReconnectAsync(controller);

        // A driver that does not report its progress cannot say what ran: the host sends it again.
        int ranTwice = released - 3;
        Assert.Equal(Enumerable.Range(1, 20), executed);
        Assert.Equal(20 + ranTwice, controller.RequestsExecuted);
        Assert.Equal(new Vector(400, 0, 590 + 10 * ranTwice), controller.State.Position);
        await bot.DisconnectAsync();
    }

    [Fact]
    public async Task Connect_ControllerBusyWithAnotherRobotsActions_IsRefusedUntilTheOwnerReconnects()
    {
        await using var controller = await StartKukaAsync();
        var (owner, executed, _) = await ConnectKukaAsync(controller);
        controller.StopAnswering();
        owner.MoveTo(Start.X, Start.Y, Start.Z);
        owner.Move(0, 0, 10);
        await EventuallyAsync(() => controller.BufferedRequestCount == 2, "both actions to reach the controller");
        await owner.DisconnectAsync();

        var stranger = Robot.Create("Stranger", "KUKA");
        stranger.ControlMode("online");
        var refused = await Assert.ThrowsAsync<RobotConnectionException>(() => stranger.ConnectAsync("127.0.0.1", controller.Port).WaitAsync(Limit));
        Assert.Contains("still executing requests this robot did not send (last executed 0, last received 2)", refused.Message, StringComparison.Ordinal);

        await owner.ConnectAsync("127.0.0.1", controller.Port).WaitAsync(Limit);
        controller.ResumeAnswering();
        await owner.WaitForCompletionAsync().WaitAsync(Limit);
        await owner.FlushEventsAsync().WaitAsync(Limit);
        Assert.Equal([1, 2], executed);
        Assert.Equal(2, controller.RequestsExecuted);
        Assert.Equal(new Vector(400, 0, 410), controller.State.Position);
    }

    /// <summary>
    /// Issues twenty moves, loses the connection after three acknowledgements while the controller runs every action it
    /// holds (their acknowledgements are lost), reconnects and waits for the end. Returns how many actions it held.
    /// </summary>
    private static async Task<(Robot Bot, ConcurrentQueue<int> Executed, int Released)> RunWhileDisconnectedAndReconnectAsync(VirtualKukaController controller)
    {
        var (bot, executed, lost) = await ConnectKukaAsync(controller);
        int released = await IssueTwentyWhilePausedAsync(bot, controller);
        controller.CloseConnectionAfter(3);
        controller.ResumeAnswering();
        await lost.Task.WaitAsync(Limit);
        await EventuallyAsync(() => controller.RequestsExecuted == released, "the controller to run what it holds, acknowledgements lost");

        await bot.ConnectAsync("127.0.0.1", controller.Port).WaitAsync(Limit);
        await bot.WaitForCompletionAsync().WaitAsync(Limit);
        await bot.FlushEventsAsync().WaitAsync(Limit);
        return (bot, executed, released);
    }

    /// <summary>Issues MoveTo(400, 0, 400) and 19 moves of +10 mm in Z with the controller paused; returns how many reached it.</summary>
    private static async Task<int> IssueTwentyWhilePausedAsync(Robot bot, VirtualKukaController controller)
    {
        controller.StopAnswering();
        bot.MoveTo(Start.X, Start.Y, Start.Z);
        for (int i = 0; i < 19; i++)
        {
            bot.Move(0, 0, 10);
        }
        int released = bot.GetReleasedState().LastAction!.Id;
        Assert.InRange(released, 4, 19);
        await EventuallyAsync(() => controller.BufferedRequestCount == released, "the released block to reach the controller");
        return released;
    }

    private static void AssertEachOnce(VirtualKukaController controller, ConcurrentQueue<int> executed)
    {
        Assert.Equal(Enumerable.Range(1, 20), executed);
        Assert.Equal(20, controller.RequestsExecuted);
        Assert.Equal(Enumerable.Range(1, 20), ReceivedIds(controller));
        Assert.Equal(new Vector(400, 0, 590), controller.State.Position);
        Assert.Empty(controller.Errors);
    }
}
