using System.Collections.Concurrent;
using Machina.Simulation;
using static Machina.Tests.Online.KukaTestSupport;
using static Machina.Tests.Online.OnlineTestSupport;

namespace Machina.Tests.Online;

/// <summary>
/// Reconnections to the virtual KUKA running the unchanged KRL driver, which reports its state and progress (<c>S</c> with
/// Executed and Received) on every connection. The driver serves a connection only at the top of its loop, between two
/// actions: while the controller does not answer (<c>StopAnswering</c>: the program is held at the acknowledgement of the
/// action it just ran) a client that connects gets the state once the program goes on, as on a KR C4 whose program was
/// stopped. So these tests connect first and resume then (the shared <see cref="ReconnectContract{TController, TState}"/>
/// reconnects while the controller is still held, which a driver that serves connections only between actions cannot do).
/// </summary>
public class KukaReconnectTests
{
    private static readonly Vector Start = new(400, 0, 400);

    private static Task<VirtualKukaController> StartAsync() => StartKukaAsync(new VirtualKukaControllerOptions { InstantExecution = true });

    [Fact]
    public async Task Reconnect_ControllerStillHoldsActions_RunsEachOnceAfterTheProgramGoesOn()
    {
        await using var controller = await StartAsync();
        var (bot, executed, lost) = await ConnectKukaAsync(controller);
        int released = await IssueTwentyWhilePausedAsync(bot, controller);
        controller.CloseConnectionAfter(3);
        controller.ResumeAnswering(3);

        await lost.Task.WaitAsync(Limit);
        await bot.FlushEventsAsync().WaitAsync(Limit);
        Assert.Equal([1, 2, 3], executed);
        Assert.Equal((3, released - 3), (controller.RequestsExecuted, controller.BufferedRequestCount));

        // The held program greets the new connection when it goes on.
        int connections = controller.ConnectionCount;
        Task connecting = bot.ConnectAsync("127.0.0.1", controller.Port);
        await ConnectionArrivedAsync(controller, connecting, connections);
        controller.ResumeAnswering();
        await connecting.WaitAsync(Limit);
        Assert.Equal(2, controller.ConnectionCount);
        await bot.WaitForCompletionAsync().WaitAsync(Limit);
        await bot.FlushEventsAsync().WaitAsync(Limit);

        AssertEachOnce(controller, executed);
        await bot.DisconnectAsync();
    }

    [Fact]
    public async Task Reconnect_ControllerRanTheRestWhileDisconnected_CountsThemExecutedAndKeepsTargets()
    {
        await using var controller = await StartAsync();
        var (bot, executed, lost) = await ConnectKukaAsync(controller);
        int released = await IssueTwentyWhilePausedAsync(bot, controller);
        controller.CloseConnectionAfter(3);
        controller.ResumeAnswering();
        await lost.Task.WaitAsync(Limit);
        // The driver runs what its ring holds; with nobody connected it sends no acknowledgement, so the controller counts them
        // executed when the next connection's state reports them. The arm shows they ran.
        var last = new Vector(400, 0, 400 + 10 * (released - 1));
        await EventuallyAsync(() => controller.State.Position.IsSimilar(last, 1e-6), "the driver to run what it holds");

        await bot.ConnectAsync("127.0.0.1", controller.Port).WaitAsync(Limit);
        await bot.WaitForCompletionAsync().WaitAsync(Limit);
        await bot.FlushEventsAsync().WaitAsync(Limit);

        AssertEachOnce(controller, executed);
        await bot.DisconnectAsync();
    }

    [Fact]
    public async Task Connect_ControllerBusyWithAnotherRobotsActions_IsRefusedUntilTheOwnerReconnects()
    {
        await using var controller = await StartAsync();
        var (owner, executed, _) = await ConnectKukaAsync(controller);
        controller.StopAnswering();
        owner.MoveTo(Start.X, Start.Y, Start.Z);
        owner.Move(0, 0, 10);
        await EventuallyAsync(() => controller.BufferedRequestCount == 2, "both actions to reach the controller");
        // The driver ran action 1 while the owner was connected, so it waits at that action's acknowledgement.
        await EventuallyAsync(() => controller.State.Position.IsSimilar(Start, 1e-6), "the driver to run action 1");
        await owner.DisconnectAsync();
        // The driver's channel saw the owner leave: the driver will open it again at the top of its loop, not send action 2 to it.
        await EventuallyAsync(() => !controller.DriverChannelConnected, "the driver's channel to see the owner leave");

        // The stranger waits at the port while the program is held after action 1; once it goes on, the driver's loop finds the
        // owner gone, opens the channel again, takes the stranger and reports action 2 received and not executed.
        var stranger = Robot.Create("Stranger", "KUKA");
        stranger.ControlMode("online");
        stranger.ConnectTimeout = Limit;
        int connections = controller.ConnectionCount;
        Task connecting = stranger.ConnectAsync("127.0.0.1", controller.Port);
        await ConnectionArrivedAsync(controller, connecting, connections);
        controller.ResumeAnswering(1);
        var refused = await Assert.ThrowsAsync<RobotConnectionException>(() => connecting.WaitAsync(Limit));
        Assert.Contains("still executing requests this robot did not send (last executed 1, last received 2)", refused.Message, StringComparison.Ordinal);
        Assert.False(stranger.IsConnected);

        Task reconnecting = owner.ConnectAsync("127.0.0.1", controller.Port);
        controller.ResumeAnswering();
        await reconnecting.WaitAsync(Limit);
        await owner.WaitForCompletionAsync().WaitAsync(Limit);
        await owner.FlushEventsAsync().WaitAsync(Limit);
        Assert.Equal([1, 2], executed);
        Assert.Equal(2, controller.RequestsExecuted);
        Assert.Equal([1, 2], controller.ExecutedIds);
        Assert.True(controller.State.Position.IsSimilar(new Vector(400, 0, 410), 1e-6), $"the robot ended at {controller.State.Position}");
    }

    [Fact]
    public async Task Reconnect_ActionsHeldOnTheHostForAFullRing_SentAfterTheOnesTheControllerHolds()
    {
        await using var controller = await StartAsync();
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
        int connections = controller.ConnectionCount;
        Task connecting = bot.ConnectAsync("127.0.0.1", controller.Port);
        await ConnectionArrivedAsync(controller, connecting, connections);
        controller.ResumeAnswering();
        await connecting.WaitAsync(Limit);
        await bot.WaitForCompletionAsync().WaitAsync(Limit);
        await bot.FlushEventsAsync().WaitAsync(Limit);

        Assert.Equal(Enumerable.Range(1, 150), executed);
        Assert.Equal(Enumerable.Range(1, 150), ReceivedIds(controller));
        Assert.Equal(Enumerable.Range(1, 150), controller.ExecutedIds);
        Assert.Equal(150, controller.RequestsExecuted);
        Assert.True(controller.State.Position.IsSimilar(new Vector(400, 10, 400), 1e-6), $"the robot ended at {controller.State.Position}");
        Assert.Empty(controller.Errors);
        await bot.DisconnectAsync();
    }

    /// <summary>
    /// Waits until a connection started by <paramref name="connecting"/> reached the controller: waiting at the driver's port
    /// (the program is held before the top of its loop), taken by the driver's channel (it got there while idle), or done.
    /// </summary>
    private static Task ConnectionArrivedAsync(VirtualKukaController controller, Task connecting, int before) =>
        EventuallyAsync(() => controller.ClientWaiting || controller.ConnectionCount > before || connecting.IsCompleted,
            "the connection to reach the driver's port");

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
        Assert.Equal(Enumerable.Range(1, 20), controller.ExecutedIds);
        Assert.Equal(Enumerable.Range(1, 20), ReceivedIds(controller));
        Assert.True(controller.State.Position.IsSimilar(new Vector(400, 0, 590), 1e-6), $"the robot ended at {controller.State.Position}");
        Assert.Empty(controller.Errors);
    }
}
