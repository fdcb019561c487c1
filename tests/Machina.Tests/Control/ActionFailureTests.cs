namespace Machina.Tests.Control;

/// <summary>Truthful outcomes: an action the controller could not run fails, what ran before it is executed, the rest is cancelled.</summary>
public class ActionFailureTests
{
    private static readonly Joints Home = new(0, 0, 0, 0, 90, 0);

    private sealed class Recorder
    {
        internal readonly List<int> Executed = [];
        internal readonly List<ActionFailedArgs> Failed = [];
        internal readonly List<ControllerStoppedArgs> Stopped = [];
        internal readonly List<ConnectionLostArgs> Lost = [];

        internal Recorder(Robot bot)
        {
            bot.ActionExecuted += (_, e) => Executed.Add(e.LastAction.Id);
            bot.ActionFailed += (_, e) => Failed.Add(e);
            bot.ControllerStopped += (_, e) => Stopped.Add(e);
            bot.ConnectionLost += (_, e) => Lost.Add(e);
        }
    }

    /// <summary>An online robot whose next connection uses <c>drivers[0]</c> (the test may replace it).</summary>
    private static Robot CreateRobot(FakeDriver[] drivers, bool connect = true)
    {
        var bot = Robot.Create("Online", "ABB");
        bot.DriverFactory = () => drivers[0];
        bot.ControlMode("online");
        if (connect)
        {
            bot.Connect("127.0.0.1", 7000);
        }
        return bot;
    }

    /// <summary>MoveTo(400, 0, 400) then nine Move(10, 0, 0): ids 1 to 10; the default window sends ids 1 to 8.</summary>
    private static Robot StartProgram(FakeDriver driver, out Recorder seen) => StartProgram([driver], out seen);

    private static Robot StartProgram(FakeDriver[] drivers, out Recorder seen)
    {
        FakeDriver driver = drivers[0];
        var bot = CreateRobot(drivers);
        seen = new Recorder(bot);
        bot.MoveTo(400, 0, 400);
        for (int i = 0; i < 9; i++)
        {
            bot.Move(10, 0, 0);
        }
        Assert.Equal(Enumerable.Range(1, 8), driver.Sent.Select(a => a.Id));
        return bot;
    }

    [Fact]
    public async Task OnFailed_WhileSendingTheFirstActionOfOneDo_CancelsTheSecond_NeverLeavesItPending()
    {
        // The controller refuses the first move the moment it is sent, on the session's loop (which runs on the issuing thread):
        // the failure must still see the second action of the same Do and cancel it, not leave it pending behind a closed link.
        var driver = new FakeDriver();
        driver.OnSent = a =>
        {
            if (a.Id == 1)
            {
                driver.Listener!.OnFailed(1, "Position outside reach.", "50050");
            }
        };
        var bot = CreateRobot([driver]);
        var seen = new Recorder(bot);

        bot.Do("MoveTo(2000, 0, 500); MoveTo(400, 0, 400);");
        OnlineRobot.Flush(bot);

        ActionFailedArgs failed = Assert.Single(seen.Failed);
        Assert.Equal(1, failed.Action.Id);
        Assert.Equal("Position outside reach.", failed.Reason);
        Assert.Equal([2], failed.CancelledActions.Select(a => a.Id));
        Assert.Empty(bot.GetPendingActions());
        Assert.Empty(seen.Executed);
        var thrown = await Assert.ThrowsAsync<ActionFailedException>(() => bot.WaitForCompletionAsync());
        Assert.Same(failed.Failure, thrown);
    }

    [Fact]
    public async Task OnFailed_MidProgram_BeforeExecuted_FailedReported_RestCancelled_WaitThrows()
    {
        var driver = new FakeDriver();
        var bot = StartProgram(driver, out var seen);
        Task waiting = bot.WaitForCompletionAsync();
        RobotAction failing = driver.Sent.ElementAt(3);

        driver.Ack(1);
        driver.Listener!.OnMotion(new MotionSample(new Vector(432, 0, 400), Rotation.FlippedAroundY, Home, null));
        driver.Listener!.OnFailed(4, "Position outside reach.", "E42");
        OnlineRobot.Flush(bot);

        Assert.Equal([1, 2, 3], seen.Executed);   // 2 and 3 were never acknowledged, but the controller ran them in order
        ActionFailedArgs failed = Assert.Single(seen.Failed);
        Assert.Same(failing, failed.Action);
        Assert.Equal("Position outside reach.", failed.Reason);
        Assert.Equal("E42", failed.Failure.ControllerCode);
        Assert.Equal(Enumerable.Range(5, 6), failed.CancelledActions.Select(a => a.Id));
        Assert.Equal(new Vector(432, 0, 400), failed.Position);   // where the robot really stopped (its last live pose)
        Assert.Empty(seen.Lost);

        ControllerStoppedArgs stopped = Assert.Single(seen.Stopped);
        Assert.True(stopped.IsStopped);
        Assert.Same(failed.Failure, stopped.Reason);
        Assert.Empty(stopped.PendingActions);

        var error = await Assert.ThrowsAsync<ActionFailedException>(() => waiting.WaitAsync(OnlineRobot.Timeout));
        Assert.Same(failing, error.Action);
        Assert.Equal($"The controller could not run {failing.ToInstruction()} (id 4): Position outside reach. (code E42) Nothing after it was executed.",
            error.Message);
        Assert.Same(error, await Assert.ThrowsAsync<ActionFailedException>(() => bot.WaitForCompletionAsync()));   // still, until the next connection

        Assert.Equal(ConnectionState.Disconnected, bot.ConnectionState);
        Assert.True(driver.Disposed);
        Assert.Empty(bot.GetPendingActions());
        Assert.Equal(Enumerable.Range(1, 8), driver.Sent.Select(a => a.Id));   // 9 and 10 never sent
        Assert.Equal(new Vector(432, 0, 400), bot.GetIssuedState().Position);
        Assert.Equal(new Vector(432, 0, 400), bot.GetReleasedState().Position);
        Assert.Equal(new Vector(432, 0, 400), bot.GetExecutedState().Position);
    }

    [Fact]
    public async Task OnFailed_ThenMoveAndConnect_MoveIsRelativeToTheReportedPose_NothingCancelledResent()
    {
        var driver = new FakeDriver();
        FakeDriver[] drivers = [driver];
        var bot = StartProgram(drivers, out var seen);
        driver.Ack(2);
        driver.Listener!.OnFailed(3, "Joint 2 out of range.", null);
        OnlineRobot.Flush(bot);
        Assert.Equal([1, 2], seen.Executed);
        Assert.Equal(new Vector(410, 0, 400), bot.GetIssuedState().Position);   // no live pose: where its last executed action left it

        bot.Move(0, 0, 10);   // id 11, issued while disconnected: relative to where the robot is
        Assert.Equal(new Vector(410, 0, 410), bot.GetIssuedState().Position);
        var error = await Assert.ThrowsAsync<RobotConnectionException>(() => bot.WaitForCompletionAsync());
        Assert.StartsWith("1 action waits to be executed, but the controller stopped after a failure (The controller could not run ", error.Message);
        Assert.IsType<ActionFailedException>(error.InnerException);

        var next = new FakeDriver
        {
            Handshake = new("1.5.0", new Vector(411, 0, 399), Rotation.FlippedAroundY, Home, null),
        };
        drivers[0] = next;
        bot.Connect("127.0.0.1", 7000);
        Assert.Equal([11], next.Sent.Select(a => a.Id));
        Assert.Equal(new Vector(411, 0, 409), bot.GetReleasedState().Position);   // recomputed from the pose the controller reports
        next.Ack(11);
        await bot.WaitForCompletionAsync().WaitAsync(OnlineRobot.Timeout);
        OnlineRobot.Flush(bot);
        Assert.Equal([1, 2, 11], seen.Executed);
        Assert.Single(seen.Failed);
    }

    [Fact]
    public void OnFailed_AfterTheFailure_LateAcknowledgementsOfTheClosedLinkAreIgnored()
    {
        var driver = new FakeDriver();
        var bot = StartProgram(driver, out var seen);
        driver.Listener!.OnFailed(1, "Collision detected.", "50204");
        driver.Ack(2);   // a closed link's report: never makes a cancelled action executed
        OnlineRobot.Flush(bot);
        Assert.Empty(seen.Executed);
        Assert.Equal(Enumerable.Range(2, 9), Assert.Single(seen.Failed).CancelledActions.Select(a => a.Id));
        Assert.Equal(ConnectionState.Disconnected, bot.ConnectionState);
    }

    [Fact]
    public void OnFailed_UnknownId_IsALinkFault_EveryActionKept()
    {
        var driver = new FakeDriver();
        var bot = StartProgram(driver, out var seen);
        driver.Listener!.OnFailed(99, "Unknown.", null);
        OnlineRobot.Flush(bot);
        Assert.Empty(seen.Failed);
        ConnectionLostArgs lost = Assert.Single(seen.Lost);
        Assert.Equal("The controller reported that it could not run action 99, which is not waiting for execution: Unknown.", lost.Error.Message);
        Assert.Equal(10, lost.PendingActions.Count);
        Assert.Equal(10, bot.GetPendingActions().Count);
    }

    [Fact]
    public void OnFailed_BeforeTheLinkIsCurrent_AppliedOnceItIs()
    {
        var driver = new FakeDriver();
        FakeDriver[] drivers = [driver];
        var bot = CreateRobot(drivers, connect: false);
        var seen = new Recorder(bot);
        bot.MoveTo(400, 0, 400);
        bot.Move(10, 0, 0);
        bot.Connect("127.0.0.1", 7000);
        Assert.Equal([1, 2], driver.Sent.Select(a => a.Id));
        driver.Ack(1);

        // The next connection's controller reports a failure of action 2 while the handshake is under way.
        var next = new FakeDriver
        {
            Handshake = new("1.6.0", new Vector(405, 0, 400), Rotation.FlippedAroundY, Home, null, new DeviceProgress(1, 2)),
            DuringConnect = listener => listener.OnFailed(2, "Position outside reach.", null),
        };
        drivers[0] = next;
        bot.Disconnect();
        bot.Connect("127.0.0.1", 7000);
        OnlineRobot.Flush(bot);

        Assert.Equal([1], seen.Executed);
        Assert.Equal(2, Assert.Single(seen.Failed).Action.Id);
        Assert.Equal(ConnectionState.Disconnected, bot.ConnectionState);
        Assert.Empty(next.Sent);
        Assert.True(next.Disposed);
    }

    [Fact]
    public void ActionFailedArgs_ToJsonString_ListsTheCancelledIds()
    {
        var bot = Robot.Create("Json", "ABB");
        bot.MoveTo(400, 0, 400);
        bot.Move(10, 0, 0);
        bot.Move(10, 0, 0);
        RobotState state = bot.GetIssuedState();
        var actions = bot.GetProgramActions();
        var args = new ActionFailedArgs(new ActionFailedException(actions[0], "Out of reach.", "E1"), [actions[1], actions[2]], state);
        Assert.StartsWith("{\"event\":\"action-failed\",\"last\":\"MoveTo(400,0,400);\",\"id\":1,", args.ToJsonString());
        Assert.Contains(",\"error\":\"Out of reach.\",\"code\":\"E1\",\"cancelled\":[2,3],\"pos\":[420,0,400],", args.ToJsonString());
        Assert.Contains(",\"cancelled\":[],", new ActionFailedArgs(args.Failure, state).ToJsonString());
    }
}
