namespace Machina.Tests.Control;

public class OnlineSessionTests
{
    private static void IssueMoves(Robot bot, int count)
    {
        for (int i = 0; i < count; i++)
        {
            bot.Move(i % 2 == 0 ? 10 : -10, 0, 0);
        }
    }

    /// <summary>A robot online through a first fake driver (the next connection uses <paramref name="next"/>), with MoveTo(400, 0, 400) and 11 moves issued.</summary>
    private static (Robot Bot, FakeDriver First, List<int> Executed) ConnectAndIssueTwelve(FakeDriver next)
    {
        var first = new FakeDriver();
        var drivers = new Queue<FakeDriver>([first, next]);
        var bot = Robot.Create("Again", "ABB");
        bot.DriverFactory = () => drivers.Dequeue();
        bot.ControlMode("online");
        bot.Connect("127.0.0.1", 7000);
        var executed = new List<int>();
        bot.ActionExecuted += (_, e) => executed.Add(e.LastAction.Id);
        bot.MoveTo(400, 0, 400);
        IssueMoves(bot, 11);
        return (bot, first, executed);
    }

    [Fact]
    public void Connect_Handshake_InitialisesEveryCursor()
    {
        var driver = new FakeDriver
        {
            Handshake = new("1.5.0", new Vector(100, 200, 300), Rotation.FromQuaternion(0, 0, 1, 0), new Joints(1, 2, 3, 4, 5, 6), new ExternalAxes(1800)),
        };
        var bot = OnlineRobot.Create(driver);

        Assert.True(bot.IsConnected);
        Assert.Equal("fake:1", bot.GetIP());
        foreach (RobotState s in new[] { bot.GetIssuedState(), bot.GetReleasedState(), bot.GetExecutedState() })
        {
            Assert.Equal(new Vector(100, 200, 300), s.Position);
            Assert.Equal(new Joints(1, 2, 3, 4, 5, 6), s.Axes);
            Assert.Equal(1800, s.ExternalAxesCartesian!.Value[1]);
            Assert.Equal(1800, s.ExternalAxesJoints!.Value[1]);
            Assert.Equal(20, s.Speed);
        }
        Assert.Null(bot.GetMotionState());
        // Relative joint motions are possible right away (and relative Cartesian ones, see the other tests).
        bot.Axes(0, 0, 0, 0, 0, 10);
        Assert.Equal(new Joints(1, 2, 3, 4, 5, 16), bot.GetIssuedState().Axes);
    }

    /// <summary>
    /// A driver with a buffer of its own (KUKA's ring of 100 slots) limits what the session releases, whatever the window
    /// allows: released means sent, and the rest of the block goes out as acknowledgements free room (no hidden second window).
    /// </summary>
    [Fact]
    public void Release_DriverCapacityThree_BlockOfTenGoesOutAsRoomFrees()
    {
        var driver = new FakeDriver { Capacity = 3 };
        var bot = OnlineRobot.Create(driver);
        bot.BlockSize = 10;
        bot.PendingCount = 10;

        IssueMoves(bot, 10);
        Assert.Equal([1, 2, 3], driver.Sent.Select(a => a.Id));
        Assert.Equal(3, bot.GetReleasedState().LastAction!.Id);
        driver.Ack(1);
        Assert.Equal([1, 2, 3, 4], driver.Sent.Select(a => a.Id));
        driver.Ack(2);
        driver.Ack(3);
        Assert.Equal([1, 2, 3, 4, 5, 6], driver.Sent.Select(a => a.Id));
        for (int id = 4; id <= 10; id++)
        {
            driver.Ack(id);
        }
        Assert.Equal(Enumerable.Range(1, 10), driver.Sent.Select(a => a.Id));
        Assert.Equal(3, driver.MaxUnacknowledged);
        Assert.True(bot.WaitForCompletion(TimeSpan.FromSeconds(10)));
    }

    [Fact]
    public void Release_BlockSizeFourPendingTwo_ReleasesExactBlocks()
    {
        var driver = new FakeDriver();
        var bot = OnlineRobot.Create(driver);
        bot.BlockSize = 4;
        bot.PendingCount = 2;

        IssueMoves(bot, 10);
        Assert.Equal(4, driver.Sent.Count);               // 0 < 2: one block of 4, then 4 >= 2: wait
        Assert.Equal([1, 2, 3, 4], driver.Sent.Select(a => a.Id));

        driver.Ack(1);
        driver.Ack(2);
        Assert.Equal(4, driver.Sent.Count);               // 2 left: not fewer than 2
        driver.Ack(3);
        Assert.Equal(8, driver.Sent.Count);               // 1 left: next block
        for (int id = 4; id <= 7; id++)
        {
            driver.Ack(id);
        }
        Assert.Equal(10, driver.Sent.Count);              // only 2 were left to release
        driver.Ack(8);
        driver.Ack(9);
        driver.Ack(10);
        Assert.Equal(Enumerable.Range(1, 10), driver.Sent.Select(a => a.Id));
        Assert.Equal(5, driver.MaxUnacknowledged);        // (pendingCount - 1) + blockSize
        Assert.Empty(bot.GetPendingActions());
    }

    [Fact]
    public void Release_Defaults_NeverMoreThanTenOnTheDevice()
    {
        var driver = new FakeDriver();
        var bot = OnlineRobot.Create(driver);
        IssueMoves(bot, 30);
        Assert.Equal(8, driver.Sent.Count);
        int next = 1;
        while (next <= 30)
        {
            driver.Ack(next++);
        }
        Assert.Equal(30, driver.Sent.Count);
        Assert.Equal(10, driver.MaxUnacknowledged);
    }

    [Fact]
    public void Release_SettingsChangedWhileStreaming_TakeEffectAtTheNextBlock()
    {
        var driver = new FakeDriver();
        var bot = OnlineRobot.Create(driver);
        IssueMoves(bot, 20);
        Assert.Equal(8, driver.Sent.Count);
        bot.BlockSize = 2;
        bot.PendingCount = 1;
        for (int id = 1; id <= 7; id++)
        {
            driver.Ack(id);
        }
        Assert.Equal(8, driver.Sent.Count);               // 1 left, not fewer than 1
        driver.Ack(8);
        Assert.Equal(10, driver.Sent.Count);
    }

    [Fact]
    public async Task Events_HelloRobotOnline_InOrderWithPayloads()
    {
        var driver = new FakeDriver();
        var bot = OnlineRobot.Create(driver);
        var log = new List<string>();
        var executed = new List<ActionExecutedArgs>();
        bot.ActionIssued += (_, e) => log.Add($"I{e.LastAction.Id}");
        bot.ActionReleased += (_, e) => log.Add($"R{e.LastAction.Id}:{e.PendingRelease}");
        bot.ActionExecuted += (_, e) => { log.Add($"E{e.LastAction.Id}:{e.PendingExecutionOnDevice}/{e.PendingExecutionTotal}"); executed.Add(e); };

        Support.ReferencePrograms.HelloRobot(bot);
        for (int id = 1; id <= 7; id++)
        {
            driver.Ack(id);
        }
        await bot.WaitForCompletionAsync().WaitAsync(OnlineRobot.Timeout);

        Assert.Equal(
            ["I1", "R1:0", "I2", "R2:0", "I3", "R3:0", "I4", "R4:0", "I5", "R5:0", "I6", "R6:0", "I7", "R7:0",
             "E1:6/6", "E2:5/5", "E3:4/4", "E4:3/3", "E5:2/2", "E6:1/1", "E7:0/0"],
            log);
        Assert.Equal(100, executed[1].State.Speed);
        Assert.Equal(new Vector(400, 300, 500), executed[2].Position);
        Assert.Equal(0.70710678, executed[3].Rotation!.Value.W, 6);
        Assert.Equal(0.70710678, executed[3].Rotation!.Value.Y, 6);
        Assert.Equal(new Vector(400, 300, 750), executed[4].Position);
        Assert.Equal(new Joints(0, 0, 0, 0, 90, 0), executed[6].Axes);
        Assert.Null(executed[6].Position);
        Assert.Equal(new Joints(0, 0, 0, 0, 90, 0), bot.GetCurrentAxes());
    }

    [Fact]
    public void Execute_ActionWithoutAcknowledgement_RunsWhenItsTurnComes()
    {
        var driver = new FakeDriver();
        var bot = OnlineRobot.Create(driver);
        var executed = new List<int>();
        bot.ActionExecuted += (_, e) => executed.Add(e.LastAction.Id);

        bot.Move(10, 0, 0);               // 1 acked
        bot.MotionMode("joint");          // 2 nothing to send
        bot.Move(0, 10, 0);               // 3 acked
        OnlineRobot.Flush(bot);
        Assert.Empty(executed);
        driver.Ack(1);
        OnlineRobot.Flush(bot);
        Assert.Equal([1, 2], executed);   // the motion mode follows the move before it at once
        Assert.Equal(MotionType.Joint, bot.GetExecutedState().MotionType);
        driver.Ack(3);
        OnlineRobot.Flush(bot);
        Assert.Equal([1, 2, 3], executed);
    }

    [Fact]
    public void Ack_LaterId_CatchesUpEarlierActionsOnce()
    {
        var driver = new FakeDriver();
        var bot = OnlineRobot.Create(driver);
        var executed = new List<int>();
        bot.ActionExecuted += (_, e) => executed.Add(e.LastAction.Id);
        IssueMoves(bot, 3);
        driver.Ack(3);
        OnlineRobot.Flush(bot);
        Assert.Equal([1, 2, 3], executed);
    }

    [Theory]
    [InlineData(99)]  // never sent
    [InlineData(1)]   // already executed (duplicate)
    public async Task Ack_UnknownId_ReportsFaultKeepsPendingExecutesNothingTwice(int badId)
    {
        var driver = new FakeDriver();
        var bot = OnlineRobot.Create(driver);
        var executed = new List<int>();
        var lost = new List<ConnectionLostArgs>();
        bot.ActionExecuted += (_, e) => executed.Add(e.LastAction.Id);
        bot.ConnectionLost += (_, e) => lost.Add(e);
        IssueMoves(bot, 12);
        driver.Ack(1);
        Task wait = bot.WaitForCompletionAsync();

        driver.Ack(badId);

        var ex = await Assert.ThrowsAsync<RobotConnectionException>(() => wait.WaitAsync(OnlineRobot.Timeout));
        Assert.Contains($"acknowledged action {badId}", ex.Message, StringComparison.Ordinal);
        Assert.Equal($"@{badId}", ex.ReceivedText);
        OnlineRobot.Flush(bot);
        Assert.Equal([1], executed);
        Assert.False(bot.IsConnected);
        Assert.True(driver.Disposed);
        Assert.Single(lost);
        Assert.Equal(Enumerable.Range(2, 11), lost[0].PendingActions.Select(a => a.Id));
        Assert.Equal(Enumerable.Range(2, 11), bot.GetPendingActions().Select(a => a.Id));
        Assert.Equal(new Vector(310, 0, 500), bot.GetExecutedState().Position);
    }

    [Fact]
    public async Task Reconnect_AfterFault_ResendsPendingAndExecutesEachActionOnce()
    {
        var second = new FakeDriver(autoAcknowledge: true);
        var (bot, first, executed) = ConnectAndIssueTwelve(second);
        first.Ack(1);
        first.Ack(2);
        first.Listener!.OnFault(new RobotConnectionException("socket closed"));
        Assert.False(bot.IsConnected);
        Assert.Equal(10, bot.GetPendingActions().Count);

        second.Handshake = second.Handshake with { Position = new Vector(410, 0, 400) };
        bot.Connect("127.0.0.1", 7000);
        await bot.WaitForCompletionAsync().WaitAsync(OnlineRobot.Timeout);

        Assert.Equal(Enumerable.Range(1, 12), executed);
        Assert.Equal(Enumerable.Range(3, 10), second.Sent.Select(a => a.Id));
        // Relative moves were recomputed from the pose the controller reported at reconnection.
        Assert.Equal(new Vector(410, 0, 400), bot.GetExecutedState().Position);
    }

    [Fact]
    public async Task Reconnect_ProgressReported_ExecutedCountHeldAdoptedRestResentWithUnchangedTargets()
    {
        var second = new FakeDriver();
        var (bot, first, executed) = ConnectAndIssueTwelve(second);
        int released = first.Sent.Count;
        Assert.True(released >= 6);
        first.Ack(1);
        first.Ack(2);
        first.Listener!.OnFault(new RobotConnectionException("socket closed"));

        // The controller ran up to 4 and still holds 5 and 6; where it says the robot is does not move the program.
        second.Handshake = second.Handshake with { Version = "1.6.0", Position = new Vector(999, 0, 0), Progress = new DeviceProgress(4, 6) };
        bot.Connect("127.0.0.1", 7000);
        OnlineRobot.Flush(bot);
        Assert.Equal([1, 2, 3, 4], executed);
        Assert.Equal(new Vector(410, 0, 400), bot.GetExecutedState().Position); // MoveTo, +10, -10, +10
        Assert.Equal([5, 6], second.Adopted);
        Assert.Equal(Enumerable.Range(7, 6), second.Sent.Select(a => a.Id));
        Assert.Equal(new Vector(410, 0, 400), bot.GetReleasedState().Position); // then -10, +10 held

        for (int id = 5; id <= 12; id++)
        {
            second.Ack(id);
        }
        await bot.WaitForCompletionAsync().WaitAsync(OnlineRobot.Timeout);
        Assert.Equal(Enumerable.Range(1, 12), executed);
        Assert.Equal(new Vector(410, 0, 400), bot.GetExecutedState().Position);
    }

    [Fact]
    public void Connect_ControllerBusyWithUnknownRequests_RefusedAndDisconnected()
    {
        var driver = new FakeDriver { Handshake = new FakeDriver().Handshake with { Version = "1.6.0", Progress = new DeviceProgress(3, 7) } };
        var bot = OnlineRobot.Create(driver, connect: false);

        var error = Assert.Throws<RobotConnectionException>(() => bot.Connect("127.0.0.1", 7000));
        Assert.Contains("last executed 3, last received 7", error.Message, StringComparison.Ordinal);
        Assert.False(bot.IsConnected);
        Assert.True(driver.Disposed);
    }

    [Fact]
    public async Task ClearPendingActions_DropsUnreleasedAndRewindsIssueState()
    {
        var driver = new FakeDriver();
        var bot = OnlineRobot.Create(driver);
        IssueMoves(bot, 11);                        // 8 released, 3 buffered; 11 moves alternate +10/-10 → x = 310
        Assert.Equal(new Vector(310, 0, 500), bot.GetIssuedState().Position);

        Assert.Equal(3, bot.ClearPendingActions());

        Assert.Equal(8, bot.GetPendingActions().Count);
        Assert.Equal(new Vector(300, 0, 500), bot.GetIssuedState().Position);
        for (int id = 1; id <= 8; id++)
        {
            driver.Ack(id);
        }
        await bot.WaitForCompletionAsync().WaitAsync(OnlineRobot.Timeout);
        Assert.Equal(8, driver.Sent.Count);
        bot.Move(0, 0, 5);
        Assert.Equal(12, driver.Sent.Last().Id);    // ids of cancelled actions are never reused
    }

    [Fact]
    public async Task Events_HandlerThrows_LinkKeepsRunning()
    {
        var driver = new FakeDriver(autoAcknowledge: true);
        var bot = OnlineRobot.Create(driver);
        var errors = new List<string>();
        bot.Logger.Logged += (_, e) => { if (e.Level == LogLevel.ERROR) { lock (errors) { errors.Add(e.Message); } } };
        int seen = 0;
        bot.ActionExecuted += (_, _) => throw new InvalidOperationException("boom");
        bot.ActionExecuted += (_, _) => Interlocked.Increment(ref seen);

        IssueMoves(bot, 20);
        await bot.WaitForCompletionAsync().WaitAsync(OnlineRobot.Timeout);

        Assert.Equal(20, seen);
        Assert.Equal(20, errors.Count);
        Assert.Contains("InvalidOperationException: boom", errors[0], StringComparison.Ordinal);
        Assert.True(bot.IsConnected);
    }

    [Fact]
    public async Task Events_IssueFromExecutedHandler_NoDeadlockAndOrdered()
    {
        var driver = new FakeDriver(autoAcknowledge: true);
        var bot = OnlineRobot.Create(driver);
        var done = new TaskCompletionSource();
        var gate = new object();
        int loops = 0, lastOfBatch = 0;
        void Batch()
        {
            lock (gate)
            {
                IssueMoves(bot, 4);
                lastOfBatch = bot.GetIssuedState().LastAction!.Id;
            }
        }
        bot.ActionExecuted += (_, e) =>
        {
            // Nothing pending after the last action of a batch (an earlier one may also find nothing pending when the
            // controller is faster than the issuing loop). The gate makes the batch and its last id one step.
            lock (gate)
            {
                if (e.PendingExecutionTotal == 0 && e.LastAction.Id == lastOfBatch)
                {
                    if (++loops == 5) { done.TrySetResult(); return; }
                    Batch();
                }
            }
        };
        Batch();
        await done.Task.WaitAsync(OnlineRobot.Timeout);
        Assert.Equal(Enumerable.Range(1, 20), driver.Sent.Select(a => a.Id));
    }

    [Fact]
    public async Task Stream_HundredThousandActions_KeepsNothingExecuted()
    {
        var driver = new FakeDriver(autoAcknowledge: true);
        var bot = OnlineRobot.Create(driver);
        bot.BlockSize = 64;
        bot.PendingCount = 32;
        for (int i = 0; i < 100_000; i++)
        {
            bot.Move(i % 2 == 0 ? 1 : -1, 0, 0);
            if (i % 1000 == 0)
            {
                while (driver.Sent.TryDequeue(out _)) { }
            }
        }
        await bot.WaitForCompletionAsync().WaitAsync(TimeSpan.FromSeconds(30));
        Assert.Empty(bot.GetPendingActions());
        Assert.Empty(bot.GetProgramActions());
        Assert.Equal(new Vector(300, 0, 500), bot.GetExecutedState().Position);
        Assert.Equal(100_000, bot.GetExecutedState().LastAction!.Id);
    }

    [Fact]
    public async Task Disconnect_WithActionsOnTheDevice_KeepsThemPendingAndFailsTheWaiter()
    {
        var driver = new FakeDriver();
        var bot = OnlineRobot.Create(driver);
        IssueMoves(bot, 5);
        driver.Ack(1);
        Task wait = bot.WaitForCompletionAsync();

        await bot.DisconnectAsync();

        var error = await Assert.ThrowsAsync<RobotConnectionException>(() => wait.WaitAsync(OnlineRobot.Timeout));
        Assert.Contains("disconnected", error.Message, StringComparison.Ordinal);
        Assert.True(driver.Disposed);
        Assert.Equal([2, 3, 4, 5], bot.GetPendingActions().Select(a => a.Id));
        await Assert.ThrowsAsync<RobotConnectionException>(() => bot.WaitForCompletionAsync());
        Assert.True(bot.ControlMode("offline"));
    }

    [Fact]
    public async Task WaitForCompletion_FromAnEventHandler_FailsInsteadOfDeadlocking()
    {
        var driver = new FakeDriver(autoAcknowledge: true);
        var bot = OnlineRobot.Create(driver);
        var seen = new TaskCompletionSource<Exception?>();
        bot.ActionExecuted += (_, _) => seen.TrySetResult(bot.WaitForCompletionAsync().Exception?.InnerException);
        bot.Move(0, 0, 10);
        Exception? error = await seen.Task.WaitAsync(OnlineRobot.Timeout);
        Assert.IsType<InvalidOperationException>(error);
        Assert.Contains("event handler", error!.Message, StringComparison.Ordinal);
    }

    [Fact]
    public void ControlMode_WhileConnected_Throws()
    {
        var bot = OnlineRobot.Create(new FakeDriver());
        var ex = Assert.Throws<InvalidOperationException>(() => bot.ControlMode("offline"));
        Assert.Contains("Disconnect", ex.Message, StringComparison.Ordinal);
        Assert.Throws<InvalidOperationException>(() => bot.Connect("127.0.0.1", 7000));
    }

    [Fact]
    public void ControlMode_Stream_IsOnlineAndConnectOfflineThrows()
    {
        var bot = Robot.Create("M", "ABB");
        Assert.Throws<InvalidOperationException>(() => bot.Connect("127.0.0.1", 7000));
        Assert.True(bot.ControlMode("Stream"));
        Assert.Equal(ControlType.Online, bot.GetControlMode());
        Assert.True(bot.ConnectionManager("machina"));   // an ABB: Connect installs the driver through Robot Web Services
        Assert.True(bot.ConnectionManager(ConnectionType.User));
        Assert.False(Robot.Create("K", "KUKA").ConnectionManager("machina"));
        Assert.Throws<ArgumentException>(() => Robot.Create("H", "HUMAN").ControlMode("online"));
        Assert.Throws<ArgumentException>(() => Robot.Create("Z", "ZMORPH").ControlMode("online"));
        foreach (string arm in new[] { "UR", "KUKA" })
        {
            var other = Robot.Create("O", arm);
            Assert.True(other.ControlMode("online"));
            Assert.Equal(ControlType.Online, other.GetControlMode());
        }
    }
}
