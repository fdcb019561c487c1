using System.Collections.Concurrent;
using Machina.Simulation;
using Machina.Tests.Support;
using static Machina.Tests.Online.OnlineTestSupport;

namespace Machina.Tests.Online;

public class AbbOnlineTests
{
    [Fact]
    public async Task HelloRobot_Online_EveryActionReleasedAndExecutedOnceInOrder()
    {
        // HelloRobot's (400, 300, 750) is beyond an IRB 120's reach (the model would stop the driver there): an arm without a
        // model, starting where the IRB 120's flange is.
        await using var controller = await StartControllerAsync(new VirtualAbbControllerOptions { SpeedFactor = 20, Model = null, InitialPosition = new Vector(302, 0, 558) });
        Robot bot = await ConnectAsync(controller);
        var released = new List<int>();
        var executed = new List<ActionExecutedArgs>();
        bot.ActionReleased += (_, e) => released.Add(e.LastAction.Id);
        bot.ActionExecuted += (_, e) => executed.Add(e);

        // Figure 5 of the paper: the issue cursor is ahead, execution follows.
        Assert.Equal(new Vector(302, 0, 558), bot.GetExecutedState().Position);
        controller.StopAnswering();
        ReferencePrograms.HelloRobot(bot);
        Assert.Equal(new Joints(0, 0, 0, 0, 90, 0), bot.GetIssuedState().Axes);
        Assert.Equal(new Vector(302, 0, 558), bot.GetExecutedState().Position);
        Assert.Equal(new Joints(0, 0, 0, 0, 90, 0), bot.GetReleasedState().Axes);
        controller.ResumeAnswering();
        await bot.WaitForCompletionAsync().WaitAsync(Limit);

        Assert.Equal([1, 2, 3, 4, 5, 6, 7], released);
        Assert.Equal([1, 2, 3, 4, 5, 6, 7], executed.Select(e => e.LastAction.Id));
        Assert.Equal([6, 5, 4, 3, 2, 1, 0], executed.Select(e => e.PendingExecutionTotal));
        Assert.Equal(100, executed[1].State.Speed);
        Assert.Equal(new Vector(400, 300, 500), executed[2].Position);
        Assert.Equal(new Vector(400, 300, 750), executed[4].Position);
        Assert.Equal(0.7071, executed[4].Rotation!.Value.W, 4);
        Assert.Equal(0.7071, executed[4].Rotation!.Value.Y, 4);
        // The twin runs an IRB 1600-8/1.45 when no model is given, and says so when asked: the robot learned it on connect,
        // so the joint move has its forward kinematics pose.
        Assert.Equal("IRB 1600-8/1.45", bot.Model?.Name);
        Assert.True(executed[6].Position!.Value.IsSimilar(new Vector(750, 0, 1121.5), 1e-6), executed[6].Position.ToString());
        Assert.Equal(new Joints(0, 0, 0, 0, 90, 0), executed[6].Axes);
        Assert.Equal(
            ["@1 7 \"Hello Robot!\";", "@2 4 100;", "@3 1 400 300 500 0 0 1 0;", "@4 1 400 300 500 0.7071 0 0.7071 0;",
             "@5 1 400 300 750 0.7071 0 0.7071 0;", "@6 6 2;", "@7 3 0 0 0 0 90 0;"],
            controller.ReceivedRequests);
        await EventuallyAsync(() => controller.AcknowledgementsSent == 7, "the controller to count its acknowledgements");
        Assert.Equal(["Hello Robot!"], controller.PendantMessages.Where(m => m == "Hello Robot!"));
        Assert.Equal(new Joints(0, 0, 0, 0, 90, 0), controller.State.Joints);
        Assert.Equal(new Joints(0, 0, 0, 0, 90, 0), bot.GetCurrentAxes());
        await bot.DisconnectAsync();
    }

    [Fact]
    public async Task Release_BlockSizeFourPendingTwo_ControllerNeverHoldsMoreThanFive()
    {
        // What the host releases while the controller does not answer is its window: one block. The controller's network
        // stack receives it whole (the RAPID driver then reads it 80 characters at a time, once it ran what it read).
        await using var controller = await StartControllerAsync(new VirtualAbbControllerOptions { InstantExecution = true });
        Robot bot = await ConnectAsync(controller, b => { b.BlockSize = 4; b.PendingCount = 2; });
        controller.StopAnswering();
        bot.MoveTo(400, 0, 400);
        for (int i = 0; i < 39; i++)
        {
            bot.Move(i % 2 == 0 ? 10 : -10, 0, 0);
        }
        await EventuallyAsync(() => controller.RequestsReceived >= 4, "the first block");
        Assert.Equal(4, controller.RequestsReceived);     // one block, then the window is closed
        Assert.Equal(4, bot.GetReleasedState().LastAction!.Id);
        Assert.Equal(0, controller.AcknowledgementsSent);
        Assert.Equal(40, bot.GetPendingActions().Count);

        controller.ResumeAnswering();
        await bot.WaitForCompletionAsync().WaitAsync(Limit);

        Assert.Equal(40, controller.RequestsReceived);
        Assert.InRange(controller.MaxUnacknowledged, 4, 5); // (pendingCount - 1) + blockSize
        Assert.Equal(new Vector(410, 0, 400), bot.GetExecutedState().Position);
        await bot.DisconnectAsync();
    }

    [Fact]
    public async Task Release_Defaults_ControllerNeverHoldsMoreThanTen()
    {
        await using var controller = await StartControllerAsync();
        Robot bot = await ConnectAsync(controller);
        bot.MoveTo(400, 0, 400);
        for (int i = 0; i < 299; i++)
        {
            bot.Move(i % 2 == 0 ? 10 : -10, 0, 0);
        }
        await bot.WaitForCompletionAsync().WaitAsync(Limit);
        await EventuallyAsync(() => controller.AcknowledgementsSent == 300, "the controller to count its acknowledgements");
        // The window caps what the controller holds; how close it gets to the cap depends on scheduling, so only the cap is asserted.
        Assert.InRange(controller.MaxUnacknowledged, 1, 10);
    }

    [Fact]
    public async Task MotionUpdates_ArriveBetweenAcknowledgements()
    {
        // The controller's clock moves only when the test says so, one monitor period at a time, and each step waits
        // until the host has seen the report it caused: the order of events is then the same on every machine.
        var clock = new ManualClock();
        var period = TimeSpan.FromMilliseconds(10);
        // The monitor task's reports are counted as they reach its socket, for this step-by-step clock.
        await using var controller = await StartControllerAsync(new VirtualAbbControllerOptions { MonitorPeriod = period, TimeProvider = clock, Model = null });
        var log = new ConcurrentQueue<(string Kind, int Id, Vector? Position)>();
        int updates = 0;
        Robot bot = await ConnectAsync(controller, b =>
        {
            b.ActionExecuted += (_, e) => log.Enqueue(("E", e.LastAction.Id, e.Position));
            b.MotionUpdate += (_, e) =>
            {
                log.Enqueue(("M", 0, e.Position));
                Interlocked.Increment(ref updates);
            };
        });
        bot.SpeedTo(200);
        bot.MoveTo(400, 0, 500);
        bot.Move(100, 0, 0);
        bot.Move(0, 100, 0);
        Task done = bot.WaitForCompletionAsync();
        for (int step = 0; step < 500 && !done.IsCompleted; step++)
        {
            await EventuallyAsync(() => clock.HasTimerDueIn(period), "the monitor to wait for its next report");
            await EventuallyAsync(() => Volatile.Read(ref updates) == controller.MonitorReportsSent, "the host to see every report");
            clock.Advance(period);
        }
        await done.WaitAsync(Limit);
        await bot.FlushEventsAsync().WaitAsync(Limit);

        var events = log.ToList();
        int e3 = events.FindIndex(x => x is ("E", 3, _));
        int e4 = events.FindIndex(x => x is ("E", 4, _));
        Assert.True(e3 >= 0 && e4 > e3);
        var between = events.Skip(e3 + 1).Take(e4 - e3 - 1).ToList();
        Assert.All(between, x => Assert.Equal("M", x.Kind));
        // 100 mm at 200 mm/s is 0.5 s, so about 50 periods, each with its report. The twin's arm is part-way while it moves, and a
        // MoveL keeps the tool on its straight line: every report lies on the segment from (500, 0, 500) to (500, 100, 500), in
        // order along it; reports sent in the same clock step as an acknowledgement travel on another socket and may arrive on
        // either side of it, hence the range.
        Assert.InRange(between.Count, 49, 60);
        Assert.All(between, x => Assert.True(
            Math.Abs(x.Position!.Value.X - 500) < 1e-2 && Math.Abs(x.Position!.Value.Z - 500) < 1e-2 && x.Position!.Value.Y is > -1e-2 and < 100.01,
            x.Position!.Value.ToString()));
        double[] along = between.Select(x => x.Position!.Value.Y).ToArray();
        Assert.All(along.Zip(along.Skip(1)), p => Assert.True(p.Second >= p.First - 1e-6, $"{p.First} then {p.Second}"));
        Assert.True(along.Count(y => y is > 1 and < 99) >= 45, "the arm is part-way while it moves: " + string.Join(", ", along));
        Assert.NotNull(bot.GetMotionState());
    }

    [Fact]
    public async Task Fault_ControllerClosesSocket_ReportsAndKeepsUnexecutedForReconnect()
    {
        await using var controller = await StartControllerAsync();
        Robot bot = await ConnectAsync(controller);
        var executed = new ConcurrentQueue<int>();
        var lost = new TaskCompletionSource<ConnectionLostArgs>(TaskCreationOptions.RunContinuationsAsynchronously);
        bot.ActionExecuted += (_, e) => executed.Enqueue(e.LastAction.Id);
        bot.ConnectionLost += (_, e) => lost.TrySetResult(e);
        controller.StopAnswering();
        bot.MoveTo(400, 0, 400);
        for (int i = 0; i < 19; i++)
        {
            bot.Move(0, 0, 10);
        }
        Task wait = bot.WaitForCompletionAsync();
        controller.CloseConnectionAfter(3);
        controller.ResumeAnswering();

        ConnectionLostArgs args = await lost.Task.WaitAsync(Limit);
        var error = await Assert.ThrowsAsync<RobotConnectionException>(() => wait.WaitAsync(Limit));
        Assert.Contains("closed the connection", error.Message, StringComparison.Ordinal);
        Assert.False(bot.IsConnected);
        await bot.FlushEventsAsync().WaitAsync(Limit);
        Assert.Equal([1, 2, 3], executed);
        Assert.Equal(Enumerable.Range(4, 17), args.PendingActions.Select(a => a.Id));
        Assert.StartsWith("{\"event\":\"connection-lost\",\"error\":\"The controller closed the connection.\",\"pending\":17,\"pos\":[400,0,420]",
            args.ToJsonString(), StringComparison.Ordinal);
        Assert.Equal(Enumerable.Range(4, 17), bot.GetPendingActions().Select(a => a.Id));
        Assert.Equal(new Vector(400, 0, 420), bot.GetExecutedState().Position);

        // A fresh controller where the robot stopped: it does not know the kept actions, whose outcome is therefore unknown
        // (docs/reliability.md, "Controller restarts"); this program may run them twice, so it asks for them to be sent again,
        // and each is executed once. Its arm is the twin's IRB 1600 (no model): an IRB 120 cannot reach (400, 0, 560) with the
        // tool flipped.
        await using var second = await StartControllerAsync(new VirtualAbbControllerOptions
        {
            Model = null,
            InstantExecution = true,
            InitialPosition = new Vector(400, 0, 420),
            InitialRotation = Rotation.FlippedAroundY,
        });
        bot.ResendAfterControllerRestart = true;
        await bot.ConnectAsync("127.0.0.1", second.Port).WaitAsync(Limit);
        await bot.WaitForCompletionAsync().WaitAsync(Limit);
        Assert.Equal(Enumerable.Range(1, 20), executed);
        await EventuallyAsync(() => second.AcknowledgementsSent == 17, "the controller to count its acknowledgements");
        Assert.Equal("@4 1 400 0 430 0 0 1 0;", second.ReceivedRequests[0]);
        Assert.True(second.State.Position.IsSimilar(new Vector(400, 0, 590), 1e-6), $"the arm ended at {second.State.Position}"); // through the IRB 1600's kinematics
        await bot.DisconnectAsync();
    }

    [Theory]
    [InlineData("hello;", "hello")]
    [InlineData("@x 1;", "@x 1")]
    [InlineData("$21 1 2 abc 0 0 1 0;", "abc")]
    [InlineData("@-5 1;", "@-5 1;")]
    [InlineData("@1 1 done;", "@1 1 done;")]
    public async Task Fault_Garbage_ReportsProtocolErrorWithReceivedText(string garbage, string expectedInText)
    {
        await using var controller = await StartControllerAsync();
        Robot bot = await ConnectAsync(controller);
        var lost = new TaskCompletionSource<ConnectionLostArgs>(TaskCreationOptions.RunContinuationsAsynchronously);
        bot.ConnectionLost += (_, e) => lost.TrySetResult(e);
        controller.StopAnswering();
        bot.MoveTo(400, 0, 400);
        Task wait = bot.WaitForCompletionAsync();

        Assert.True(await controller.SendRawAsync(garbage));

        ConnectionLostArgs args = await lost.Task.WaitAsync(Limit);
        var error = Assert.IsType<AbbProtocolException>(args.Error);
        Assert.Contains(expectedInText, error.ReceivedText, StringComparison.Ordinal);
        Assert.Same(error, await Assert.ThrowsAsync<AbbProtocolException>(() => wait.WaitAsync(Limit)));
        Assert.Equal([1], bot.GetPendingActions().Select(a => a.Id));
        controller.ResumeAnswering();
    }

    [Fact]
    public async Task Fault_AcknowledgementOfUnknownId_ReportsAndExecutesNothing()
    {
        await using var controller = await StartControllerAsync();
        Robot bot = await ConnectAsync(controller);
        int executed = 0;
        var lost = new TaskCompletionSource<ConnectionLostArgs>(TaskCreationOptions.RunContinuationsAsynchronously);
        bot.ActionExecuted += (_, _) => Interlocked.Increment(ref executed);
        bot.ConnectionLost += (_, e) => lost.TrySetResult(e);
        controller.StopAnswering();
        bot.MoveTo(400, 0, 400);

        Assert.True(await controller.SendAcknowledgementAsync(999, 1));

        ConnectionLostArgs args = await lost.Task.WaitAsync(Limit);
        Assert.Contains("acknowledged action 999", args.Error.Message, StringComparison.Ordinal);
        await bot.FlushEventsAsync().WaitAsync(Limit);
        Assert.Equal(0, executed);
        Assert.Equal([1], bot.GetPendingActions().Select(a => a.Id));
        controller.ResumeAnswering();
    }

    [Fact]
    public async Task Fault_ControllerStopsAnswering_TimesOutAndReports()
    {
        await using var controller = await StartControllerAsync();
        // The host's clock moves only when the test says so: no answer can be "late" by accident on a slow machine.
        var hostClock = new ManualClock();
        Robot bot = await ConnectAsync(controller, b =>
        {
            b.ResponseTimeout = TimeSpan.FromSeconds(1);
            b.Time = hostClock;
        });
        var lost = new TaskCompletionSource<ConnectionLostArgs>(TaskCreationOptions.RunContinuationsAsynchronously);
        bot.ConnectionLost += (_, e) => lost.TrySetResult(e);
        bot.MoveTo(400, 0, 400);
        await bot.WaitForCompletionAsync().WaitAsync(Limit);
        controller.StopAnswering();
        bot.Move(0, 0, 10);
        bot.Move(0, 0, 10);
        Task wait = bot.WaitForCompletionAsync();
        // The RAPID driver reads what has arrived (up to 80 characters), runs it, then waits to send its acknowledgement, which
        // the controller now holds: it has read one move or both, depending on when the second arrived. Either way it is held.
        await EventuallyAsync(() => controller.BufferedRequestCount >= 1, "the first move to reach the controller");
        hostClock.Advance(TimeSpan.FromSeconds(0.9));
        Assert.False(lost.Task.IsCompleted);
        Assert.True(bot.IsConnected);
        hostClock.Advance(TimeSpan.FromSeconds(60));

        ConnectionLostArgs args = await lost.Task.WaitAsync(Limit);
        Assert.Contains("stopped answering", args.Error.Message, StringComparison.Ordinal);
        await Assert.ThrowsAsync<RobotConnectionException>(() => wait.WaitAsync(Limit));
        Assert.Equal([2, 3], bot.GetPendingActions().Select(a => a.Id));
        controller.ResumeAnswering();
    }

    [Fact]
    public async Task Connect_NothingListening_ThrowsMachinaException()
    {
        var listener = new System.Net.Sockets.TcpListener(System.Net.IPAddress.Loopback, 0);
        listener.Start();
        int port = ((System.Net.IPEndPoint)listener.LocalEndpoint).Port;
        listener.Stop();
        var bot = Robot.Create("Nobody", "ABB");
        bot.ControlMode("online");

        var error = await Assert.ThrowsAsync<RobotConnectionException>(() => bot.ConnectAsync("127.0.0.1", port).WaitAsync(Limit));
        Assert.Contains($"127.0.0.1:{port}", error.Message, StringComparison.Ordinal);
        Assert.False(bot.IsConnected);
    }

    [Fact]
    public async Task ConnectAsync_CancelledWhileWaitingForHandshake_ThrowsAndStaysDisconnected()
    {
        await using var server = SilentServer.Start();
        var bot = Robot.Create("Cancelled", "ABB");
        bot.ControlMode("online");
        using var cancel = new CancellationTokenSource();
        Task connecting = bot.ConnectAsync("127.0.0.1", server.Port, cancel.Token);
        await server.Accepted.WaitAsync(Limit);
        await cancel.CancelAsync();

        await Assert.ThrowsAnyAsync<OperationCanceledException>(() => connecting.WaitAsync(Limit));
        Assert.False(bot.IsConnected);
    }

    [Fact]
    public async Task Connect_NoHandshake_TimesOut()
    {
        // The robot's clock moves only when the test says so: a slow machine cannot turn this into a connect timeout.
        await using var server = SilentServer.Start();
        var clock = new ManualClock();
        var bot = Robot.Create("Silent", "ABB");
        bot.ControlMode("online");
        bot.Time = clock;
        bot.ConnectTimeout = TimeSpan.FromMilliseconds(300);

        Task connecting = bot.ConnectAsync("127.0.0.1", server.Port);
        await server.Accepted.WaitAsync(Limit);
        // The handshake's timer; on Linux a peer that answers at once is connected without a deadline timer of its own.
        await EventuallyAsync(() => clock.TimersCreated == (OperatingSystem.IsLinux() ? 1 : 2), "the robot to wait for the handshake (after the TCP connect)");
        Assert.False(connecting.IsCompleted);
        clock.Advance(TimeSpan.FromMilliseconds(300));

        var error = await Assert.ThrowsAsync<RobotConnectionException>(() => connecting.WaitAsync(Limit));
        Assert.Contains("did not send its handshake within 0.3 s", error.Message, StringComparison.Ordinal);
        Assert.False(bot.IsConnected);
    }
}

public class AbbOnlineWireTests
{
    [Fact]
    public async Task Connect_Handshake_PoseJointsAndExternalAxesInEveryCursorAndMotionUpdates()
    {
        // The driver reports the joints its arm has and the flange pose its kinematics give them (an IRB 120 here); the twin's arm
        // has no external axes, so every one is reported as 9E9 (none).
        var joints = new Joints(10, 20, 30, 40, 50, 60);
        Pose flange = RobotModels.Get("IRB 120").Kinematics.Forward(joints);
        await using var controller = await OnlineTestSupport.StartControllerAsync(new VirtualAbbControllerOptions
        {
            InstantExecution = true,
            InitialJoints = joints,
        });
        var bot = Robot.Create("Handshake", "ABB");
        bot.ControlMode("online");
        var motion = new TaskCompletionSource<MotionUpdateArgs>(TaskCreationOptions.RunContinuationsAsynchronously);
        bot.MotionUpdate += (_, e) => motion.TrySetResult(e);
        await bot.ConnectAsync("127.0.0.1", controller.Port).WaitAsync(OnlineTestSupport.Limit);

        foreach (RobotState s in new[] { bot.GetIssuedState(), bot.GetReleasedState(), bot.GetExecutedState() })
        {
            // The handshake carries millimetres with 3 decimals and joints with 3 decimals.
            Assert.True(s.Position!.Value.IsSimilar(flange.Position, 1e-3), s.Position.ToString());
            Assert.Equal(joints, s.Axes);
            Assert.Null(s.ExternalAxesCartesian);
            Assert.Null(s.ExternalAxesJoints);
        }
        Assert.True(((Vector)bot.GetCurrentPosition()!.Value).IsSimilar(flange.Position, 1e-3));
        MotionUpdateArgs update = await motion.Task.WaitAsync(OnlineTestSupport.Limit);
        Assert.Equal(joints, update.Axes);
        Assert.True(update.Position!.Value.IsSimilar(flange.Position, 1e-3), update.Position.ToString());
        Assert.Null(update.ExternalAxes);
        await bot.DisconnectAsync();
        Assert.False(bot.IsConnected);
        Assert.Equal("", bot.GetIP());
    }

    [Fact]
    public async Task Stream_SettingsToolsIOAndAxes_ExactRequestsOneAcknowledgementEach()
    {
        await using var controller = await OnlineTestSupport.StartControllerAsync();
        Robot bot = await OnlineTestSupport.ConnectAsync(controller);
        var executed = new ConcurrentQueue<int>();
        bot.ActionExecuted += (_, e) => executed.Enqueue(e.LastAction.Id);

        bot.AccelerationTo(500);                                                         // 1
        bot.PushSettings();                                                              // 2 nothing to send
        bot.SpeedTo(50);                                                                 // 3
        bot.PrecisionTo(2);                                                              // 4
        bot.PopSettings();                                                               // 5 speed and zone restored
        bot.DefineTool("pen", new Vector(0, 0, 100), Rotation.FromQuaternion(1, 0, 0, 0), 0.5, new Vector(0, 0, 50)); // 6
        bot.AttachTool("pen");                                                           // 7
        bot.WriteDigital("DO_15", true);                                                 // 8
        bot.WriteAnalog("AO_1", 0.5);                                                    // 9
        bot.ExternalAxisTo(1, 1800);                                                     // 10 both target sets
        bot.CustomCode("103 0.05");                                                      // 11
        bot.DetachTool();                                                                // 12
        bot.MotionMode("joint");                                                         // 13 nothing to send
        bot.MoveTo(400, 0, 400);                                                         // 14
        await bot.WaitForCompletionAsync().WaitAsync(OnlineTestSupport.Limit);

        Assert.Equal(
            ["@1 13 0.5;", "@3 4 50;", "@4 5 2;", "@0 4 20;", "@5 5 5;", "@7 8 0 0 100 1 0 0 0 0.5 0 0 50;", "@8 10 \"DO_15\" 1;",
             "@9 11 \"AO_1\" 0.5;", "@0 15 1800 9E9 9E9 9E9 9E9 9E9;", "@10 16 1800 9E9 9E9 9E9 9E9 9E9;", "@11 103 0.05;", "@12 9;",
             "@14 2 400 0 400 0 0 1 0;"],
            controller.ReceivedRequests);
        Assert.Equal(Enumerable.Range(1, 14), executed);
        Assert.Equal(1800, bot.GetExecutedState().ExternalAxesJoints!.Value[1]);
        Assert.Equal(new Vector(400, 0, 400), controller.State.Position);
        Assert.True(controller.State.DigitalOutputs["DO_15"]);
        Assert.Equal(0.5, controller.State.AnalogOutputs["AO_1"]);
        Assert.Equal(20, controller.State.Speed);
        Assert.Empty(controller.Errors);
    }
}

public class AbbOnlineReferenceProgramTests
{
    public static TheoryData<string> Programs => new(ReferencePrograms.All.Keys);

    [Theory]
    [MemberData(nameof(Programs))]
    public async Task ReferenceProgram_StreamedOnline_EveryActionExecutedOnceInOrder(string name)
    {
        // HelloRobot goes beyond an IRB 120's reach (the driver would stop there, AbbFailureTests): an arm without a model for it.
        await using var controller = await OnlineTestSupport.StartControllerAsync(name == "HelloRobot"
            ? new VirtualAbbControllerOptions { InstantExecution = true, Model = null, InitialPosition = new Vector(302, 0, 558) }
            : null);
        Robot bot = await OnlineTestSupport.ConnectAsync(controller);
        var executed = new ConcurrentQueue<int>();
        bot.ActionExecuted += (_, e) => executed.Enqueue(e.LastAction.Id);

        if (name == "JointsToolsIO")
        {
            // Its numbered output (WriteDigital(1, true)) names no ABB signal: refused at issue time, as offline; what came before runs.
            var refused = Assert.Throws<ActionRefusedException>(() => ReferencePrograms.All[name](bot));
            Assert.Equal("WriteDigital(1,True);", refused.Action.ToInstruction());
        }
        else
        {
            ReferencePrograms.All[name](bot);
        }
        int issued = bot.GetIssuedState().LastAction!.Id;
        await bot.WaitForCompletionAsync().WaitAsync(OnlineTestSupport.Limit);

        Assert.Equal(Enumerable.Range(1, issued), executed);
        Assert.Empty(bot.GetPendingActions());
        await bot.DisconnectAsync();
    }
}
