using Machina.Tests.Support;

namespace Machina.Tests.Control;

/// <summary>The online seam: connection states, stops and resumes, issue-time refusals, release failures, disposal.</summary>
public class OnlineSeamTests
{
    private sealed class RefusingBrand : IOnlineBrand
    {
        public RobotType Brand => RobotType.ABB;

        public IDeviceDriver CreateDriver(DeviceContext context) => throw new InvalidOperationException("not used");

        public string? WhyCannotStream(RobotAction action) =>
            action is ActionIOAnalog ? $"{action.ToInstruction()} is not supported online on this test brand." : null;

        public ActionFrame Encode(RobotAction action, RobotCursor after, out string? refusal)
        {
            refusal = null;
            return ActionFrame.Nothing;
        }

        public IReadOnlyDictionary<string, string> DriverModules(IReadOnlyDictionary<string, string> parameters) => new Dictionary<string, string>();
    }

    [Fact]
    public void ConnectionState_Transitions_DisconnectedConnectedStoppedConnectedDisconnected()
    {
        var driver = new FakeDriver();
        var bot = OnlineRobot.Create(driver, connect: false);
        Assert.Equal(ConnectionState.Disconnected, bot.ConnectionState);
        bot.Connect("127.0.0.1", 7000);
        Assert.Equal(ConnectionState.Connected, bot.ConnectionState);

        driver.Listener!.OnStopped(new RobotStoppedException("Protective stop."));
        Assert.Equal(ConnectionState.Stopped, bot.ConnectionState);
        Assert.True(bot.IsConnected);

        driver.Listener!.OnResumed();
        Assert.Equal(ConnectionState.Connected, bot.ConnectionState);

        bot.Disconnect();
        Assert.Equal(ConnectionState.Disconnected, bot.ConnectionState);
        Assert.Equal(ConnectionState.Disconnected, Robot.Create("Off", "ABB").ConnectionState);
    }

    [Fact]
    public async Task Stopped_NothingMoreSent_WaitersFailWithTheReason_ResumeSendsTheRestOnce()
    {
        var driver = new FakeDriver();
        var bot = OnlineRobot.Create(driver);
        bot.BlockSize = 2;
        bot.PendingCount = 1;
        var stops = new List<(bool Stopped, int Pending, string? Reason)>();
        bot.ControllerStopped += (_, e) => stops.Add((e.IsStopped, e.PendingActions.Count, e.Reason?.Message));
        bot.ControllerResumed += (_, e) => stops.Add((e.IsStopped, e.PendingActions.Count, e.Reason?.Message));
        bot.MoveTo(400, 0, 400);
        for (int i = 0; i < 5; i++)
        {
            bot.Move(10, 0, 0);
        }
        Assert.Equal(2, driver.Sent.Count);

        driver.Listener!.OnStopped(new RobotStoppedException("Protective stop: the arm hit something."));
        Task waiting = bot.WaitForCompletionAsync();
        driver.Ack(driver.Sent.First().Id);   // the controller still finishes what it was doing
        driver.Ack(driver.Sent.Last().Id);
        OnlineRobot.Flush(bot);
        Assert.Equal(2, driver.Sent.Count);   // nothing more while stopped
        var error = await Assert.ThrowsAsync<RobotStoppedException>(() => waiting.WaitAsync(OnlineRobot.Timeout));
        Assert.Equal("Protective stop: the arm hit something.", error.Message);
        await Assert.ThrowsAsync<RobotStoppedException>(() => bot.WaitForCompletionAsync().WaitAsync(OnlineRobot.Timeout));

        await bot.ResumeAsync();
        Assert.Equal(ConnectionState.Connected, bot.ConnectionState);
        Assert.Equal(4, driver.Sent.Count);
        while (driver.Sent.Count < 6 || driver.Unacknowledged > 0)
        {
            driver.Ack(driver.Sent.ElementAt(driver.Sent.Count - driver.Unacknowledged).Id);
        }
        await bot.WaitForCompletionAsync().WaitAsync(OnlineRobot.Timeout);
        Assert.Equal(Enumerable.Range(1, 6), driver.Sent.Select(a => a.Id));
        Assert.Equal(new Vector(450, 0, 400), bot.GetExecutedState().Position);
        Assert.Equal([(true, 6, "Protective stop: the arm hit something."), (false, 4, null)], stops);
    }

    [Fact]
    public void Resume_NotStopped_ThrowsAndSaysWhy()
    {
        var bot = OnlineRobot.Create(new FakeDriver());
        var error = Assert.Throws<InvalidOperationException>(() => bot.Resume());
        Assert.Equal("The robot is running; there is nothing to resume.", error.Message);
    }

    [Fact]
    public void Issue_ActionTheBrandCannotStream_RefusedBeforeAnythingChanges()
    {
        var driver = new FakeDriver();
        var bot = Robot.Create("Refusing", "ABB");
        bot.DriverFactory = () => driver;
        bot.OnlineBrandOverride = new RefusingBrand();
        bot.ControlMode("online");
        bot.Connect("127.0.0.1", 7000);
        bot.MoveTo(400, 0, 400);

        var error = Assert.Throws<ActionRefusedException>(() => bot.WriteAnalog("AO_1", 3.5));
        Assert.Equal("WriteAnalog(\"AO_1\",3.5); is not supported online on this test brand.", error.Reason);
        Assert.Equal(-1, error.Action.Id);
        Assert.Empty(bot.GetIssuedState().AnalogOutputs);
        // Neither does a multi-statement text issue half of itself.
        Assert.Throws<ActionRefusedException>(() => bot.Do("Move(10, 0, 0); WriteAnalog(\"AO_1\", 1);"));
        bot.Move(0, 10, 0);
        Assert.Equal([1, 2], driver.Sent.Select(a => a.Id));
        Assert.Equal(new Vector(400, 10, 400), bot.GetIssuedState().Position);
    }

    [Fact]
    public void Release_DriverCannotEncode_LinkFaultsAndTheActionIsKeptNotSkipped()
    {
        var driver = new FakeDriver { CannotEncode = a => a is ActionWait };
        var bot = OnlineRobot.Create(driver);
        MachinaException? lost = null;
        bot.ConnectionLost += (_, e) => lost = e.Error;
        bot.MoveTo(400, 0, 400);
        bot.Wait(100);
        bot.Move(10, 0, 0);
        OnlineRobot.Flush(bot);

        Assert.Equal([1], driver.Sent.Select(a => a.Id));
        Assert.False(bot.IsConnected);
        Assert.NotNull(lost);
        Assert.StartsWith("Wait(100); (id 2) was not sent: it could not be encoded for the controller: the fake cannot encode it", lost!.Message, StringComparison.Ordinal);
        Assert.Equal([1, 2, 3], bot.GetPendingActions().Select(a => a.Id));
    }

    [Fact]
    public void Watchdog_WaitLongerThanTimeSpanCanHold_NoOverflowNoFault()
    {
        var clock = new ManualClock();
        var driver = new FakeDriver();
        var bot = Robot.Create("Patient", "ABB");
        bot.Time = clock;
        bot.DriverFactory = () => driver;
        bot.ResponseTimeout = TimeSpan.FromSeconds(1);
        bot.ControlMode("online");
        bot.Connect("127.0.0.1", 7000);
        bot.Wait(1_000_000_000);                    // the longest wait allowed; the move below is what TimeSpan cannot hold
        bot.SpeedTo(1e-9);
        bot.MoveTo(1e6, 0, 630);

        clock.Advance(TimeSpan.FromSeconds(10));   // 40 checks of the watchdog, each facing an expected duration TimeSpan cannot hold
        OnlineRobot.Flush(bot);

        Assert.True(bot.IsConnected);
        Assert.Equal(ConnectionState.Connected, bot.ConnectionState);
    }

    [Fact]
    public async Task WaitForCompletion_AfterTheLinkWasLost_NamesTheCause()
    {
        var driver = new FakeDriver();
        var bot = OnlineRobot.Create(driver);
        bot.MoveTo(400, 0, 400);
        driver.Listener!.OnFault(new RobotConnectionException("The controller closed the connection."));

        var error = await Assert.ThrowsAsync<RobotConnectionException>(() => bot.WaitForCompletionAsync());
        Assert.Equal("The connection was lost (The controller closed the connection.) while 1 action waits to be executed; connect again to resume.", error.Message);
        Assert.IsType<RobotConnectionException>(error.InnerException);
    }

    [Fact]
    public async Task DisposeAsync_QueuedEventsDropped_NoHandlerRunsAfterwards_CannotGoOnlineAgain()
    {
        var driver = new FakeDriver();
        var bot = OnlineRobot.Create(driver);
        using var inHandler = new SemaphoreSlim(0);
        using var release = new SemaphoreSlim(0);
        int executed = 0;
        bot.ActionExecuted += (_, _) =>
        {
            Interlocked.Increment(ref executed);
            inHandler.Release();
            release.Wait(OnlineRobot.Timeout);
        };
        bot.MoveTo(400, 0, 400);
        bot.Move(10, 0, 0);
        driver.Ack(1);
        Assert.True(await inHandler.WaitAsync(OnlineRobot.Timeout));
        driver.Ack(2);                                   // queued behind the running handler

        Task disposing = bot.DisposeAsync().AsTask();
        Assert.False(disposing.IsCompleted);             // waits for the running handler
        release.Release();
        await disposing.WaitAsync(OnlineRobot.Timeout);

        Assert.Equal(1, Volatile.Read(ref executed));    // the queued one was dropped
        Assert.True(driver.Disposed);
        Assert.False(bot.IsConnected);
        Assert.Throws<ObjectDisposedException>(() => bot.Connect("127.0.0.1", 7000));
        await bot.DisposeAsync();                        // twice is fine
    }

    [Fact]
    public void ControlModeOffline_QueuedEventsRaisedBeforeItReturns()
    {
        var driver = new FakeDriver();
        var bot = OnlineRobot.Create(driver, connect: false);
        int issued = 0;
        bot.ActionIssued += (_, _) =>
        {
            Thread.Yield();
            Interlocked.Increment(ref issued);
        };
        for (int i = 0; i < 50; i++)
        {
            bot.Wait(1);
        }
        bot.ControlMode("offline");
        Assert.Equal(50, Volatile.Read(ref issued));
    }

    [Fact]
    public void Compile_OnlineAfterAFailedConnect_SaysNotConnectedAndHowToCompile()
    {
        var bot = Robot.Create("Failed", "ABB");
        bot.ConnectTimeout = TimeSpan.FromMilliseconds(200);
        bot.ControlMode("online");
        using var closed = new System.Net.Sockets.TcpListener(System.Net.IPAddress.Loopback, 0);
        closed.Start();
        int port = ((System.Net.IPEndPoint)closed.LocalEndpoint).Port;
        closed.Stop();   // nothing listens there any more
        Assert.ThrowsAny<MachinaException>(() => bot.Connect("127.0.0.1", port));

        var error = Assert.Throws<InvalidOperationException>(() => bot.Compile());
        Assert.Equal("Compile works in offline mode; this robot is in online mode (not connected), so its actions wait to be streamed. "
            + "Call ControlMode(\"offline\") first to compile the actions issued from then on.", error.Message);
    }
}
