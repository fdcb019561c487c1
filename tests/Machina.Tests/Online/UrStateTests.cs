using System.Collections.Concurrent;
using Machina.Simulation;
using Machina.Tests.Support;
using static Machina.Tests.Online.OnlineTestSupport;
using static Machina.Tests.Online.UrOnlineTestSupport;

namespace Machina.Tests.Online;

/// <summary>What the host learns over RTDE and does with the dashboard: motion updates, stops and resumes, reconnects.</summary>
public class UrStateTests
{
    [Fact]
    public async Task MotionUpdates_ManualClock_ArriveAtTheConfiguredRate()
    {
        var clock = new ManualClock();
        await using var controller = await StartUrAsync(new VirtualUrControllerOptions { InstantExecution = true, TimeProvider = clock });
        int updates = 0;
        Robot bot = await ConnectUrAsync(controller, b =>
        {
            b.MotionUpdateRate = 50;
            b.MotionUpdate += (_, _) => Interlocked.Increment(ref updates);
        });
        var period = TimeSpan.FromMilliseconds(20);
        // The package the handshake reads is not an update. The driver program's start also sends one at once: when the
        // handshake read it first it is not an update either; when it came after, it is an early live pose, raised once the link
        // is current. Either way, at most one, and every period after it brings exactly one more.
        // The wake of the program's connection back to the host is sent after the host was greeted, so under load its package
        // can arrive after this count (it is then one update more at the end, never one per period more).
        await bot.FlushEventsAsync().WaitAsync(Limit);
        int initial = Volatile.Read(ref updates);
        Assert.InRange(initial, 0, 2);

        // One simulated second, one period at a time: each step is due exactly one package, and so one update.
        for (int i = 1; i <= 50; i++)
        {
            await EventuallyAsync(() => clock.HasTimerDueIn(period), "RTDE to wait for its next package");
            clock.Advance(period);
            int expected = initial + i;
            await EventuallyAsync(() => Volatile.Read(ref updates) >= expected, "the update of this period");
        }
        await bot.FlushEventsAsync().WaitAsync(Limit);
        Assert.InRange(Volatile.Read(ref updates) - initial, 50, 51);
        // The 50, the one read while connecting, and at once the driver program's start and its connection back to the host
        // (which shows the instance register the program wrote): two wakes that may come as one package or two. The client's
        // start is a wake too (it joins after the START answer): when the sender thread is between two looks it comes as a
        // package of its own (seen once in CI, 54). Never one per period more: the count of updates above holds that.
        Assert.InRange(controller.RtdePackagesSent, 52, 54);
        Assert.True(((Vector)bot.GetCurrentPosition()!.Value).IsSimilar(controller.State.Position, 1e-6));
        await bot.DisconnectAsync();
    }

    [Fact]
    public async Task ProtectiveStop_ReportedAtOnceNothingMoreSent_ResumeRunsEachActionOnce()
    {
        var clock = new ManualClock();
        await using var controller = await StartUrAsync(new VirtualUrControllerOptions { TimeProvider = clock });
        var stopped = new TaskCompletionSource<ControllerStoppedArgs>(TaskCreationOptions.RunContinuationsAsynchronously);
        var resumed = new TaskCompletionSource<ControllerStoppedArgs>(TaskCreationOptions.RunContinuationsAsynchronously);
        var executed = new ConcurrentQueue<int>();
        Robot bot = await ConnectUrAsync(controller, b =>
        {
            b.ControllerStopped += (_, e) => stopped.TrySetResult(e);
            b.ControllerResumed += (_, e) => resumed.TrySetResult(e);
            b.ActionExecuted += (_, e) => executed.Enqueue(e.LastAction.Id);
        });
        Vector start = controller.State.Position;
        for (int i = 0; i < 12; i++)
        {
            bot.Move(0, 0, -10); // 10 mm at the driver's 20 mm/s: 0.5 s each
        }
        // 10 mm at 20 mm/s with the driver's 1.2 m/s² ramps: 0.5167 s; half of its time is half of its way.
        await EventuallyAsync(() => controller.MotionDuration is TimeSpan d && clock.HasTimerDueIn(WholeMilliseconds(d)), "the first move to start");
        TimeSpan move = controller.MotionDuration!.Value;
        Assert.Equal(0.01 / 0.02 + 0.02 / 1.2, move.TotalSeconds, 1e-6);
        clock.Advance(move / 2);
        Assert.True(controller.ProtectiveStop());
        ControllerStoppedArgs stop = await stopped.Task.WaitAsync(Limit);
        Assert.Contains("protective stop", stop.Reason!.Message, StringComparison.Ordinal);
        Assert.True(controller.State.Position.IsSimilar(start + new Vector(0, 0, -5), 1e-6), controller.State.Position.ToString());
        await Assert.ThrowsAsync<RobotStoppedException>(() => bot.WaitForCompletionAsync().WaitAsync(Limit));
        int released = bot.GetReleasedState().LastAction!.Id;
        bot.Move(0, 0, -10);
        Assert.Equal(released, bot.GetReleasedState().LastAction!.Id); // nothing more is sent while stopped
        clock.Advance(TimeSpan.FromSeconds(5));
        Assert.Empty(executed);

        await bot.ResumeAsync().WaitAsync(Limit);
        await resumed.Task.WaitAsync(Limit);
        // The connect asked which arm this is (get robot model, PolyscopeVersion) before anything else.
        Assert.Equal(["get robot model", "PolyscopeVersion", "safetystatus", "close safety popup", "unlock protective stop", "play"], controller.DashboardCommands);
        // Simulated time runs until everything is done (however slowly this machine schedules the controller), bounded in real time.
        Task done = bot.WaitForCompletionAsync();
        long begun = TimeProvider.System.GetTimestamp();
        while (!done.IsCompleted && TimeProvider.System.GetElapsedTime(begun) < Limit)
        {
            clock.Advance(TimeSpan.FromSeconds(0.05));
            await Task.Delay(1);
        }
        await done.WaitAsync(Limit);
        await bot.FlushEventsAsync().WaitAsync(Limit);

        Assert.Equal(Enumerable.Range(1, 13), executed);
        Assert.Equal(13, controller.RequestsExecuted);
        Assert.True(controller.State.Position.IsSimilar(start + new Vector(0, 0, -130), 1e-6), controller.State.Position.ToString());
        Assert.Empty(controller.Errors);
        await bot.DisconnectAsync();
    }

    [Fact]
    public async Task EmergencyStop_ResumeRefusedUntilTheButtonIsReleased()
    {
        await using var controller = await StartUrAsync();
        var stopped = new TaskCompletionSource<ControllerStoppedArgs>(TaskCreationOptions.RunContinuationsAsynchronously);
        Robot bot = await ConnectUrAsync(controller, b => b.ControllerStopped += (_, e) => stopped.TrySetResult(e));
        Assert.True(controller.EmergencyStop());
        Assert.Contains("robot emergency stop", (await stopped.Task.WaitAsync(Limit)).Reason!.Message, StringComparison.Ordinal);

        var refused = await Assert.ThrowsAsync<RobotStoppedException>(() => bot.ResumeAsync().WaitAsync(Limit));
        Assert.Contains("release the emergency stop button", refused.Message, StringComparison.Ordinal);
        Assert.Equal(["get robot model", "PolyscopeVersion", "safetystatus"], controller.DashboardCommands);

        controller.ReleaseEmergencyStop();
        await bot.ResumeAsync().WaitAsync(Limit);
        bot.Move(0, 0, -10);
        await bot.WaitForCompletionAsync().WaitAsync(Limit);
        Assert.Equal(1, controller.RequestsExecuted);
        await bot.DisconnectAsync();
    }

    [Fact]
    public async Task Reconnect_AfterTheControllerDroppedTheLink_ResumesFromItsProgress_EachActionOnce()
    {
        // The driver reads one instruction at a time: what the host streamed ahead was in the connection the controller closed,
        // so the driver ran exactly the three it acknowledged; the host learns that from the progress register and sends the rest.
        await using var controller = await StartUrAsync();
        var (bot, executed, lost) = await ConnectWatchedAsync(controller);
        Vector start = controller.State.Position;
        await IssueTwentyWhilePausedAsync(bot, controller);
        controller.CloseConnectionAfter(3);
        controller.ResumeAnswering();
        await lost.Task.WaitAsync(Limit);
        Assert.Equal(3, controller.RequestsExecuted);

        await bot.ConnectAsync("127.0.0.1", controller.Port).WaitAsync(Limit);
        await bot.WaitForCompletionAsync().WaitAsync(Limit);
        await bot.FlushEventsAsync().WaitAsync(Limit);

        AssertEachOnce(controller, executed, start);
    }

    [Fact]
    public async Task Reconnect_WhileTheControllerStillHoldsItsAcknowledgements_WaitsThenSendsOnlyTheRest()
    {
        await using var controller = await StartUrAsync();
        var (bot, executed, lost) = await ConnectWatchedAsync(controller);
        Vector start = controller.State.Position;
        await IssueTwentyWhilePausedAsync(bot, controller);
        controller.CloseConnectionAfter(3);
        controller.ResumeAnswering(3);
        await lost.Task.WaitAsync(Limit);
        Assert.Equal(3, controller.RequestsExecuted); // the new program's first acknowledgement will be held again

        Task reconnect = bot.ConnectAsync("127.0.0.1", controller.Port);
        controller.ResumeAnswering();
        await reconnect.WaitAsync(Limit);
        await bot.WaitForCompletionAsync().WaitAsync(Limit);
        await bot.FlushEventsAsync().WaitAsync(Limit);

        AssertEachOnce(controller, executed, start);
    }

    /// <summary>The timer a wait of <paramref name="d"/> sets: Task.Delay counts whole milliseconds.</summary>
    internal static TimeSpan WholeMilliseconds(TimeSpan d) => TimeSpan.FromMilliseconds(Math.Floor(d.TotalMilliseconds));

    private static async Task<(Robot Bot, ConcurrentQueue<int> Executed, TaskCompletionSource Lost)> ConnectWatchedAsync(VirtualUrController controller)
    {
        var executed = new ConcurrentQueue<int>();
        var lost = new TaskCompletionSource(TaskCreationOptions.RunContinuationsAsynchronously);
        Robot bot = await ConnectUrAsync(controller, b =>
        {
            b.ActionExecuted += (_, e) => executed.Enqueue(e.LastAction.Id);
            b.ConnectionLost += (_, _) => lost.TrySetResult();
        });
        return (bot, executed, lost);
    }

    /// <summary>Issues twenty moves of -10 mm in Z with the acknowledgements held: the driver runs the first and waits at its acknowledgement.</summary>
    private static async Task IssueTwentyWhilePausedAsync(Robot bot, VirtualUrController controller)
    {
        controller.StopAnswering();
        for (int i = 0; i < 20; i++)
        {
            bot.Move(0, 0, -10);
        }
        int released = bot.GetReleasedState().LastAction!.Id;
        Assert.InRange(released, 4, 19);
        await EventuallyAsync(() => controller.RequestsReceived == 1 && controller.BufferedRequestCount == 1, "the driver to hold its first acknowledgement");
    }

    private static void AssertEachOnce(VirtualUrController controller, ConcurrentQueue<int> executed, Vector start)
    {
        Assert.Equal(Enumerable.Range(1, 20), executed);
        Assert.Equal(20, controller.RequestsExecuted);
        Assert.Equal(Enumerable.Range(1, 20), controller.ReceivedRequests.Select(r => int.Parse(r[..r.IndexOf(' ')], Num.Inv)));
        Assert.True(controller.State.Position.IsSimilar(start + new Vector(0, 0, -200), 1e-6), controller.State.Position.ToString());
        Assert.Equal(2, controller.ScriptsReceived);
        Assert.Empty(controller.Errors);
    }
}
