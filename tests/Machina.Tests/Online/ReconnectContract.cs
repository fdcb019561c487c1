using System.Collections.Concurrent;
using Machina.Simulation;
using static Machina.Tests.Online.OnlineTestSupport;

namespace Machina.Tests.Online;

/// <summary>
/// The reconnect contract of every controller whose driver reports its progress on each handshake and keeps what it holds
/// across connections (ABB <c>$25</c>, KUKA <c>S</c>): a connection lost mid-program and opened again to the same controller
/// runs every action exactly once and keeps its target, whatever the controller did while nobody was listening; a driver
/// without the report sends the unconfirmed actions again; a controller busy with another robot's actions refuses a
/// stranger. A brand's test class derives from this and says how to start its virtual controller and read what it received.
/// UR keeps a different contract (<see cref="UrStateTests"/>): its host sends a new driver program on every connection, so
/// connecting waits until the old program has run what it holds, and there is no old driver without the report.
/// </summary>
public abstract class ReconnectContract<TController, TState>
    where TController : VirtualController<TState>
    where TState : VirtualRobotState
{
    /// <summary>Where the first action of each program goes.</summary>
    protected static readonly Vector Start = new(400, 0, 400);

    /// <summary>The brand as <see cref="Robot.Create(string, string)"/> reads it.</summary>
    protected abstract string Brand { get; }

    /// <summary>A virtual controller with instant execution and the current driver, started on loopback.</summary>
    protected abstract Task<TController> StartAsync();

    /// <summary>A robot of this brand connected to <paramref name="controller"/>, set up by <paramref name="configure"/> first.</summary>
    protected abstract Task<Robot> ConnectAsync(TController controller, Action<Robot> configure);

    /// <summary>The port a robot connects to (each front end has its own <c>Port</c>).</summary>
    protected abstract int PortOf(TController controller);

    /// <summary>The ids of the actions the controller received, in order.</summary>
    protected abstract IEnumerable<int> ReceivedIds(TController controller);

    [Fact]
    public async Task Reconnect_ControllerStillHoldsActions_WaitsForThemAndSendsOnlyTheRest()
    {
        await using var controller = await StartAsync();
        var (bot, executed, lost) = await ConnectWatchedAsync(controller);
        int released = await IssueTwentyWhilePausedAsync(bot, controller);
        controller.CloseConnectionAfter(3);
        controller.ResumeAnswering(3);

        await lost.Task.WaitAsync(Limit);
        await bot.FlushEventsAsync().WaitAsync(Limit);
        Assert.Equal([1, 2, 3], executed);
        Assert.Equal((3, released - 3), (controller.RequestsExecuted, controller.BufferedRequestCount));

        await ReconnectWhileHeldAsync(bot, controller);
        await bot.WaitForCompletionAsync().WaitAsync(Limit);
        await bot.FlushEventsAsync().WaitAsync(Limit);

        AssertEachOnce(controller, executed);
        await bot.DisconnectAsync();
    }

    [Fact]
    public async Task Reconnect_ControllerRanTheRestWhileDisconnected_CountsThemExecutedAndKeepsTargets()
    {
        await using var controller = await StartAsync();
        var (bot, executed, _) = await RunWhileDisconnectedAndReconnectAsync(controller);

        // Before the progress report (ABB driver 1.6) these actions ran twice and the rest of the program was shifted by
        // their motion; the original's KUKA driver sent its state once per program run, so a reconnection timed out.
        AssertEachOnce(controller, executed);
        await bot.DisconnectAsync();
    }

    [Fact]
    public async Task Connect_ControllerBusyWithAnotherRobotsActions_IsRefusedUntilTheOwnerReconnects()
    {
        await using var controller = await StartAsync();
        var (owner, executed, _) = await ConnectWatchedAsync(controller);
        controller.StopAnswering();
        owner.MoveTo(Start.X, Start.Y, Start.Z);
        owner.Move(0, 0, 10);
        await EventuallyAsync(() => controller.BufferedRequestCount == 2, "both actions to reach the controller");
        await owner.DisconnectAsync();

        await ConnectStrangerAsync(controller);

        await ReconnectOwnerAndResumeAsync(owner, controller);
        await owner.WaitForCompletionAsync().WaitAsync(Limit);
        await owner.FlushEventsAsync().WaitAsync(Limit);
        Assert.Equal([1, 2], executed);
        Assert.Equal(2, controller.RequestsExecuted);
        AssertNear(new Vector(400, 0, 410), controller.State.Position);
    }

    /// <summary>
    /// Another robot connects while the paused controller holds the owner's two actions: refused, from the progress the handshake
    /// reports. A driver that accepts a client only once it ran what it holds overrides this.
    /// </summary>
    protected virtual async Task ConnectStrangerAsync(TController controller)
    {
        var stranger = Robot.Create("Stranger", Brand);
        stranger.ControlMode("online");
        var refused = await Assert.ThrowsAsync<RobotConnectionException>(() => stranger.ConnectAsync("127.0.0.1", PortOf(controller)).WaitAsync(Limit));
        Assert.Contains("still executing requests this robot did not send (last executed 0, last received 2)", refused.Message, StringComparison.Ordinal);
        Assert.False(stranger.IsConnected);
    }

    /// <summary>
    /// The robot connects again while the paused controller holds actions 4 and up: it waits for them (only the rest is to send),
    /// then the controller answers again. A driver that accepts a client only once it ran what it holds overrides this.
    /// </summary>
    protected virtual async Task ReconnectWhileHeldAsync(Robot bot, TController controller)
    {
        await bot.ConnectAsync("127.0.0.1", PortOf(controller)).WaitAsync(Limit);
        Assert.Equal(2, controller.ConnectionCount);
        Assert.Equal(Enumerable.Range(4, 17), bot.GetPendingActions().Select(a => a.Id));
        controller.ResumeAnswering();
    }

    /// <summary>The owner connects again to the paused controller, which then answers again.</summary>
    protected virtual async Task ReconnectOwnerAndResumeAsync(Robot owner, TController controller)
    {
        await owner.ConnectAsync("127.0.0.1", PortOf(controller)).WaitAsync(Limit);
        controller.ResumeAnswering();
    }

    /// <summary>A connected robot recording the ids it sees executed and its lost connections.</summary>
    protected async Task<(Robot Bot, ConcurrentQueue<int> Executed, TaskCompletionSource<ConnectionLostArgs> Lost)> ConnectWatchedAsync(
        TController controller, Action<Robot>? configure = null)
    {
        var executed = new ConcurrentQueue<int>();
        var lost = new TaskCompletionSource<ConnectionLostArgs>(TaskCreationOptions.RunContinuationsAsynchronously);
        Robot bot = await ConnectAsync(controller, b =>
        {
            b.ActionExecuted += (_, e) => executed.Enqueue(e.LastAction.Id);
            b.ConnectionLost += (_, e) => lost.TrySetResult(e);
            configure?.Invoke(b);
        });
        return (bot, executed, lost);
    }

    /// <summary>
    /// Issues twenty moves, loses the connection after three acknowledgements while the controller runs every action it
    /// holds (their acknowledgements are lost), reconnects and waits for the end. Returns how many actions it held.
    /// </summary>
    private async Task<(Robot Bot, ConcurrentQueue<int> Executed, int Released)> RunWhileDisconnectedAndReconnectAsync(TController controller)
    {
        var (bot, executed, lost) = await ConnectWatchedAsync(controller);
        int released = await IssueTwentyWhilePausedAsync(bot, controller);
        controller.CloseConnectionAfter(3);
        controller.ResumeAnswering();
        await lost.Task.WaitAsync(Limit);
        await EventuallyAsync(() => controller.RequestsExecuted == released, "the controller to run what it holds, acknowledgements lost");

        await bot.ConnectAsync("127.0.0.1", PortOf(controller)).WaitAsync(Limit);
        await bot.WaitForCompletionAsync().WaitAsync(Limit);
        await bot.FlushEventsAsync().WaitAsync(Limit);
        return (bot, executed, released);
    }

    /// <summary>Issues MoveTo(400, 0, 400) and 19 moves of +10 mm in Z with the controller paused; returns how many reached it.</summary>
    private static async Task<int> IssueTwentyWhilePausedAsync(Robot bot, TController controller)
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

    /// <summary>The arm's pose comes from its kinematics: equal to a micrometre.</summary>
    private static void AssertNear(Vector expected, Vector actual) => Assert.True(actual.IsSimilar(expected, 1e-3), $"expected {expected}, was {actual}");

    private void AssertEachOnce(TController controller, ConcurrentQueue<int> executed)
    {
        Assert.Equal(Enumerable.Range(1, 20), executed);
        Assert.Equal(20, controller.RequestsExecuted);
        Assert.Equal(Enumerable.Range(1, 20), ReceivedIds(controller));
        AssertNear(new Vector(400, 0, 590), controller.State.Position);
        Assert.Empty(controller.Errors);
    }
}
