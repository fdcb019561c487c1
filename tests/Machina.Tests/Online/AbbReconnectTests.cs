using System.Collections.Concurrent;
using System.Globalization;
using Machina.Simulation;
using static Machina.Tests.Online.OnlineTestSupport;

namespace Machina.Tests.Online;

/// <summary>
/// A connection lost mid-program and opened again to the same controller: with the driver's progress report (<c>$25</c>)
/// every action runs exactly once and keeps its target, whatever the controller did while nobody was listening.
/// </summary>
public class AbbReconnectTests
{
    private static readonly Vector Start = new(400, 0, 400);

    [Fact]
    public async Task Reconnect_ControllerStillHoldsRequests_WaitsForThemAndSendsOnlyTheRest()
    {
        await using var controller = await StartControllerAsync();
        var (bot, executed, lost) = await ConnectWatchedAsync(controller);
        int released = await IssueTwentyWhilePausedAsync(bot, controller);
        controller.CloseConnectionAfter(3);
        controller.ResumeAnswering(3);

        await lost.Task.WaitAsync(Limit);
        await bot.FlushEventsAsync().WaitAsync(Limit);
        Assert.Equal([1, 2, 3], executed);
        Assert.Equal((3, released - 3), (controller.RequestsExecuted, controller.BufferedRequestCount));

        await bot.ConnectAsync("127.0.0.1", controller.Port).WaitAsync(Limit);
        Assert.Equal(Enumerable.Range(4, 17), bot.GetPendingActions().Select(a => a.Id));
        controller.ResumeAnswering();
        await bot.WaitForCompletionAsync().WaitAsync(Limit);
        await bot.FlushEventsAsync().WaitAsync(Limit);

        AssertEachOnce(controller, executed);
        await bot.DisconnectAsync();
    }

    [Fact]
    public async Task Reconnect_ControllerRanTheRestWhileDisconnected_CountsThemExecutedAndKeepsTargets()
    {
        await using var controller = await StartControllerAsync();
        var (bot, executed, _) = await RunWhileDisconnectedAndReconnectAsync(controller);

        // Before driver 1.6 these actions ran twice and the rest of the program was shifted by their motion.
        AssertEachOnce(controller, executed);
        await bot.DisconnectAsync();
    }

    [Fact]
    public async Task Reconnect_DriverWithoutProgress_SendsUnconfirmedAgainFromTheReportedPose()
    {
        await using var controller = await StartControllerAsync(new VirtualAbbControllerOptions { InstantExecution = true, DriverVersion = new Version(1, 5, 0), Model = null });
        var (bot, executed, released) = await RunWhileDisconnectedAndReconnectAsync(controller);

        // The documented limit of old drivers: the host cannot know what ran, so it sends it again.
        int ranTwice = released - 3;
        Assert.Equal(Enumerable.Range(1, 20), executed);
        Assert.Equal(20 + ranTwice, controller.RequestsExecuted);
        Assert.Equal(new Vector(400, 0, 590 + 10 * ranTwice), controller.State.Position);
        await bot.DisconnectAsync();
    }

    [Fact]
    public async Task Connect_ControllerBusyWithAnotherRobotsRequests_IsRefusedUntilTheOwnerReconnects()
    {
        await using var controller = await StartControllerAsync();
        var (owner, executed, _) = await ConnectWatchedAsync(controller);
        controller.StopAnswering();
        owner.MoveTo(Start.X, Start.Y, Start.Z);
        owner.Move(0, 0, 10);
        await EventuallyAsync(() => controller.BufferedRequestCount == 2, "both requests to reach the controller");
        await owner.DisconnectAsync();

        var stranger = Robot.Create("Stranger", "ABB");
        stranger.ControlMode("online");
        var refused = await Assert.ThrowsAsync<RobotConnectionException>(() => stranger.ConnectAsync("127.0.0.1", controller.Port).WaitAsync(Limit));
        Assert.Contains("still executing requests this robot did not send (last executed 0, last received 2)", refused.Message, StringComparison.Ordinal);
        Assert.False(stranger.IsConnected);

        await owner.ConnectAsync("127.0.0.1", controller.Port).WaitAsync(Limit);
        controller.ResumeAnswering();
        await owner.WaitForCompletionAsync().WaitAsync(Limit);
        await owner.FlushEventsAsync().WaitAsync(Limit);
        Assert.Equal([1, 2], executed);
        Assert.Equal(2, controller.RequestsExecuted);
        Assert.Equal(new Vector(400, 0, 410), controller.State.Position);
    }

    /// <summary>
    /// Issues twenty moves, loses the connection after three acknowledgements while the controller runs every request it
    /// holds (their acknowledgements are lost), reconnects and waits for the end. Returns how many requests it held.
    /// </summary>
    private static async Task<(Robot Bot, ConcurrentQueue<int> Executed, int Released)> RunWhileDisconnectedAndReconnectAsync(VirtualAbbController controller)
    {
        var (bot, executed, lost) = await ConnectWatchedAsync(controller);
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

    private static async Task<(Robot Bot, ConcurrentQueue<int> Executed, TaskCompletionSource<ConnectionLostArgs> Lost)> ConnectWatchedAsync(VirtualAbbController controller)
    {
        var executed = new ConcurrentQueue<int>();
        var lost = new TaskCompletionSource<ConnectionLostArgs>(TaskCreationOptions.RunContinuationsAsynchronously);
        Robot bot = await ConnectAsync(controller, b =>
        {
            b.ActionExecuted += (_, e) => executed.Enqueue(e.LastAction.Id);
            b.ConnectionLost += (_, e) => lost.TrySetResult(e);
        });
        return (bot, executed, lost);
    }

    /// <summary>Issues MoveTo(400, 0, 400) and 19 moves of +10 mm in Z with the controller paused; returns how many reached it.</summary>
    private static async Task<int> IssueTwentyWhilePausedAsync(Robot bot, VirtualAbbController controller)
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

    private static void AssertEachOnce(VirtualAbbController controller, ConcurrentQueue<int> executed)
    {
        Assert.Equal(Enumerable.Range(1, 20), executed);
        Assert.Equal(20, controller.RequestsExecuted);
        Assert.Equal(Enumerable.Range(1, 20), controller.ReceivedRequests.Select(r => int.Parse(r[1..r.IndexOf(' ')], CultureInfo.InvariantCulture)));
        Assert.Equal(new Vector(400, 0, 590), controller.State.Position);
        Assert.Empty(controller.Errors);
    }
}
