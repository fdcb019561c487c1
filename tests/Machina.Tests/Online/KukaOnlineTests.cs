using System.Collections.Concurrent;
using Machina.Simulation;
using Machina.Tests.Support;
using static Machina.Tests.Online.KukaTestSupport;
using static Machina.Tests.Online.OnlineTestSupport;

namespace Machina.Tests.Online;

/// <summary>Online control of KUKA robots against the virtual KUKA controller, which plays Machina's KRL driver.</summary>
public class KukaOnlineTests
{
    [Fact]
    public async Task HelloRobot_Online_SevenActionsExecutedInOrderWithTheRightFinalPose()
    {
        await using var controller = await StartKukaAsync(new VirtualKukaControllerOptions { SpeedFactor = 50 });
        var (bot, executed, _) = await ConnectKukaAsync(controller);
        var states = new ConcurrentQueue<ActionExecutedArgs>();
        bot.ActionExecuted += (_, e) => states.Enqueue(e);
        Pose start = RobotModels.Get("KR 6 R900 sixx").Kinematics.Forward(new Joints(0, -90, 90, 0, 90, 0));
        Assert.True(Vector.Distance(start.Position, bot.GetCurrentPosition()!.Value) < 1e-3);

        controller.StopAnswering();
        ReferencePrograms.HelloRobot(bot);
        controller.ResumeAnswering();
        await bot.WaitForCompletionAsync().WaitAsync(Limit);
        await bot.FlushEventsAsync().WaitAsync(Limit);

        Assert.Equal([1, 2, 3, 4, 5, 6, 7], executed);
        Assert.Equal([1, 2, 3, 4, 5, 6, 7], ReceivedIds(controller));
        var e = states.ToArray();
        Assert.Equal(new Vector(400, 300, 500), e[2].Position);
        Assert.Equal(new Vector(400, 300, 750), e[4].Position);
        Assert.Equal(new Joints(0, 0, 0, 0, 90, 0), e[6].Axes);
        Assert.Equal("<A ID=\"1\" T=\"8\" V1=\"0\" V2=\"0\" V3=\"0\" V4=\"0\" V5=\"0\" V6=\"0\" V7=\"0\" M=\"Hello Robot!\"/>", controller.ReceivedRequests[0]);
        Assert.Equal("<A ID=\"2\" T=\"4\" V1=\"0.1\" V2=\"0\" V3=\"0\" V4=\"0\" V5=\"0\" V6=\"0\" V7=\"0\" M=\"\"/>", controller.ReceivedRequests[1]);
        Assert.Equal("<A ID=\"6\" T=\"7\" V1=\"2\" V2=\"0\" V3=\"0\" V4=\"0\" V5=\"0\" V6=\"0\" V7=\"0\" M=\"\"/>", controller.ReceivedRequests[5]);
        Assert.Equal("<A ID=\"7\" T=\"3\" V1=\"0\" V2=\"0\" V3=\"0\" V4=\"0\" V5=\"90\" V6=\"0\" V7=\"0\" M=\"\"/>", controller.ReceivedRequests[6]);
        await EventuallyAsync(() => controller.AcknowledgementsSent == 7, "the controller to count its acknowledgements");
        Assert.Empty(controller.Errors);
        // The driver's notification message, as the smartPAD's message window shows it: module, number, text.
        Assert.Contains("NOTIFY Machina 1: Hello Robot!", controller.PendantMessages);
        // The arm went where the host said, in the host's pose convention: after the rotation and the lift the tool is
        // at (400, 300, 750) with the host's orientation, then the axes.
        Pose final = RobotModels.Get("KR 6 R900 sixx").Kinematics.Forward(new Joints(0, 0, 0, 0, 90, 0));
        Assert.Equal(new Joints(0, 0, 0, 0, 90, 0), controller.State.Joints);
        Assert.True(Vector.Distance(final.Position, controller.State.Position) < 1e-6);
        Assert.Equal(new Joints(0, 0, 0, 0, 90, 0), bot.GetCurrentAxes());
        await bot.DisconnectAsync();
    }

    [Fact]
    public async Task HelloRobot_LiftedPose_ControllerAgreesWithTheHostsRotation()
    {
        await using var controller = await StartKukaAsync();
        var (bot, _, _) = await ConnectKukaAsync(controller);
        bot.SpeedTo(100);
        bot.MoveTo(400, 300, 500);
        bot.Rotate(0, 1, 0, -90);
        bot.Move(0, 0, 250);
        await bot.WaitForCompletionAsync().WaitAsync(Limit);

        Assert.True(Vector.Distance(new Vector(400, 300, 750), controller.State.Position) < 1e-6, $"{controller.State.Position}");
        Assert.True(controller.State.Rotation.AngleTo(bot.GetCurrentRotation()!.Value) < 1e-3);
        Assert.Empty(controller.Errors);
        await bot.DisconnectAsync();
    }

    [Fact]
    public async Task ThousandActions_ToolsIOWaitsSpeedsAndMessages_InOrderNothingLostOrRunTwice()
    {
        await using var controller = await StartKukaAsync();
        // Blocks larger than the driver's ring: the host holds what does not fit.
        var (bot, executed, _) = await ConnectKukaAsync(controller, b => { b.BlockSize = 300; b.PendingCount = 300; });
        var expectedMessages = new List<string>();
        bot.DefineTool("pen", 0, 0, 100, 1, 0, 0, 0, 1, 0, 0.5, 0, 0, 50);
        bot.MoveTo(400, 0, 500);
        int i = 0;
        while (bot.GetIssuedState().LastAction!.Id < 1000)
        {
            switch (i++ % 10)
            {
                case 0: bot.Move(10, 0, 0); break;
                case 1: bot.SpeedTo(50 + i % 7); break;
                case 2: bot.WriteDigital(1 + i % 16, i % 3 == 0); break;
                case 3:
                    string text = $"#{i} <tag> & \"quoted\" 'single'";
                    expectedMessages.Add(text);
                    bot.Message(text);
                    break;
                case 4: bot.Wait(1); break;
                case 5: bot.AttachTool("pen"); break;
                case 6: bot.PushSettings(); bot.PrecisionTo(i % 4); bot.AccelerationTo(500); break;
                case 7: bot.PopSettings(); break;
                case 8: bot.DetachTool(); bot.WriteAnalog(1, (i % 5) / 5.0); break;
                default: bot.Move(-10, 0, 0); break;
            }
        }
        await bot.WaitForCompletionAsync().WaitAsync(Limit);
        await bot.FlushEventsAsync().WaitAsync(Limit);

        int issued = bot.GetIssuedState().LastAction!.Id;
        Assert.Equal(Enumerable.Range(1, issued), executed);
        List<int> received = ReceivedIds(controller);
        Assert.Equal(received.Order(), received);
        Assert.Equal(received.Count, received.Distinct().Count());
        Assert.Equal(received.Count, controller.RequestsExecuted);
        Assert.InRange(received.Count, 900, issued);
        Assert.InRange(controller.MaxUnacknowledged, 1, KukaProtocol.Capacity);
        const string Notify = "NOTIFY Machina 1: ";
        Assert.Equal(expectedMessages, controller.PendantMessages.Where(m => m.StartsWith(Notify + "#", StringComparison.Ordinal)).Select(m => m[Notify.Length..]));
        Assert.Empty(controller.Errors);
        Assert.True(Vector.Distance(bot.GetCurrentPosition()!.Value, controller.State.Position) < 1e-6);
        Assert.True(bot.GetCurrentRotation()!.Value.AngleTo(controller.State.Rotation) < 1e-3);
        Assert.Equal(bot.GetCurrentTool() is null, controller.State.Tool is null);
        await bot.DisconnectAsync();
    }

    [Fact]
    public async Task Release_BlocksLargerThanTheRing_ControllerNeverHoldsMoreThanItsSlots()
    {
        await using var controller = await StartKukaAsync();
        var (bot, executed, _) = await ConnectKukaAsync(controller, b => { b.BlockSize = 250; b.PendingCount = 250; });
        controller.StopAnswering();
        bot.MoveTo(400, 0, 500);
        for (int i = 0; i < 249; i++)
        {
            bot.Move(0, i % 2 == 0 ? 10 : -10, 0);
        }
        await EventuallyAsync(() => controller.BufferedRequestCount == KukaProtocol.Capacity, "the ring to fill");
        // Released means sent: the session holds the rest of the block until acknowledgements free slots (no hidden window).
        Assert.Equal(KukaProtocol.Capacity, bot.GetReleasedState().LastAction!.Id);
        Assert.Equal(250 - KukaProtocol.Capacity, bot.GetPendingActions().Count(a => a.Id > KukaProtocol.Capacity));
        controller.ResumeAnswering();
        await bot.WaitForCompletionAsync().WaitAsync(Limit);
        await bot.FlushEventsAsync().WaitAsync(Limit);

        Assert.Equal(KukaProtocol.Capacity, controller.MaxUnacknowledged);
        Assert.Equal(Enumerable.Range(1, 250), executed);
        Assert.Equal(Enumerable.Range(1, 250), ReceivedIds(controller));
        Assert.Empty(controller.Errors);
        await bot.DisconnectAsync();
    }

    [Theory]
    [InlineData(AcknowledgementWrites.Joined)]
    [InlineData(AcknowledgementWrites.Split)]
    public async Task Acknowledgements_JoinedOrSplitAcrossWrites_EachActionExecutedOnce(AcknowledgementWrites writes)
    {
        await using var controller = await StartKukaAsync(new VirtualKukaControllerOptions { InstantExecution = true, AcknowledgementWrites = writes });
        var (bot, executed, _) = await ConnectKukaAsync(controller);
        controller.StopAnswering();
        bot.MoveTo(400, 0, 500);
        for (int i = 0; i < 59; i++)
        {
            bot.Move(0, i % 2 == 0 ? 10 : -10, 0);
        }
        await EventuallyAsync(() => controller.BufferedRequestCount >= 2, "a block to reach the controller");
        controller.ResumeAnswering();
        await bot.WaitForCompletionAsync().WaitAsync(Limit);
        await bot.FlushEventsAsync().WaitAsync(Limit);

        Assert.Equal(Enumerable.Range(1, 60), executed);
        Assert.Equal(Enumerable.Range(1, 60), ReceivedIds(controller));
        Assert.True(Vector.Distance(new Vector(400, 10, 500), controller.State.Position) < 1e-6, $"{controller.State.Position}");
        await bot.DisconnectAsync();
    }

    public static TheoryData<string, Action<Robot>> Refusals => new()
    {
        { "ExternalAxis", b => b.ExternalAxis(1, 10) },
        { "CustomCode", b => b.CustomCode("$OUT[1] = TRUE") },
        { "signal name", b => b.WriteDigital("DO_Gripper", true) },
        { "tool outputs", b => b.WriteDigital(1, true, true) },
        { "from -1 to 1", b => b.WriteAnalog(1, 5) },
        { "Temperature", b => b.Temperature(200, "extruder") },
    };

    [Theory]
    [MemberData(nameof(Refusals))]
    public async Task Issue_ActionTheDriverCannotRun_RefusedBeforeSendingWithItsName(string reason, Action<Robot> issue)
    {
        await using var controller = await StartKukaAsync();
        var (bot, executed, _) = await ConnectKukaAsync(controller);
        bot.Move(0, 0, 10);

        var refused = Assert.Throws<ActionRefusedException>(() => issue(bot));
        Assert.Contains("is not supported online on KUKA", refused.Message, StringComparison.Ordinal);
        Assert.Contains(reason, refused.Message, StringComparison.Ordinal);
        Assert.Contains(refused.Action.Type.ToString(), refused.Message, StringComparison.Ordinal);
        bot.Move(0, 0, 10);
        await bot.WaitForCompletionAsync().WaitAsync(Limit);
        await bot.FlushEventsAsync().WaitAsync(Limit);
        Assert.Equal([1, 2], executed);
        Assert.Equal([1, 2], ReceivedIds(controller));
        await bot.DisconnectAsync();
    }

    [Fact]
    public async Task Send_LongMessageAndToolWeight_ShownCutAndToldInTheLog()
    {
        await using var controller = await StartKukaAsync();
        var log = new ConcurrentQueue<LogEntry>();
        var (bot, _, _) = await ConnectKukaAsync(controller, b => b.Logger.Logged += (_, e) => log.Enqueue(e));
        bot.Message(new string('a', 70) + " and the rest is cut");
        bot.DefineTool("gripper", 0, 0, 120, 1, 0, 0, 0, 1, 0, 2.5, 0, 0, 60);
        bot.AttachTool("gripper");
        await bot.WaitForCompletionAsync().WaitAsync(Limit);

        Assert.Contains("NOTIFY Machina 1: " + new string('a', 70) + " and the r", controller.PendantMessages);
        Assert.Contains(log, e => e.Level == LogLevel.WARNING && e.Message.Contains("messages hold 80 characters", StringComparison.Ordinal));
        Assert.Contains(log, e => e.Level == LogLevel.WARNING && e.Message.Contains("tool \"gripper\" are not sent", StringComparison.Ordinal));
        Assert.Equal(new Pose(new Vector(0, 0, 120), Rotation.Identity), controller.State.Tool);
        await bot.DisconnectAsync();
    }

    [Fact]
    public async Task MotionUpdateRate_ReachesTheMonitor_LivePosesFeedTheMotionCursor()
    {
        await using var controller = await StartKukaAsync(new VirtualKukaControllerOptions { SpeedFactor = 20 });
        int updates = 0;
        var (bot, _, _) = await ConnectKukaAsync(controller, b =>
        {
            b.MotionUpdateRate = 25;
            b.MotionUpdate += (_, _) => Interlocked.Increment(ref updates);
        });
        await EventuallyAsync(() => controller.MonitorPeriod == TimeSpan.FromMilliseconds(40), "the monitor to take the robot's rate");
        bot.SpeedTo(200);
        bot.Move(0, 0, -100);
        await bot.WaitForCompletionAsync().WaitAsync(Limit);
        int seen = controller.MonitorReportsSent;
        await EventuallyAsync(() => Volatile.Read(ref updates) >= seen && bot.GetMotionState() is not null, "the host to see the reports");
        RobotState motion = bot.GetMotionState()!;
        await EventuallyAsync(() => Vector.Distance(bot.GetMotionState()!.Position!.Value, controller.State.Position) < 1e-2, "a report of the final pose");
        Assert.NotNull(motion.Axes);
        await bot.DisconnectAsync();
    }

    [Theory]
    [InlineData("hello", "outside an XML element")]
    [InlineData("<Q/>", "<Q>")]
    [InlineData("<R ID=\"x\"></R>", "not a whole number")]
    public async Task Fault_Garbage_ReportsProtocolErrorWithReceivedText(string garbage, string expected)
    {
        await using var controller = await StartKukaAsync();
        var (bot, _, lost) = await ConnectKukaAsync(controller);
        controller.StopAnswering();
        bot.Move(0, 0, 10);
        Task wait = bot.WaitForCompletionAsync();
        Assert.True(await controller.SendRawAsync(garbage));

        ConnectionLostArgs args = await lost.Task.WaitAsync(Limit);
        var error = Assert.IsType<KukaProtocolException>(args.Error);
        Assert.Contains(expected, error.Message, StringComparison.Ordinal);
        await Assert.ThrowsAnyAsync<MachinaException>(() => wait.WaitAsync(Limit));
        Assert.Equal([1], bot.GetPendingActions().Select(a => a.Id));
    }

    [Fact]
    public async Task Connect_ServerThatSaysNothing_TimesOutNamingTheDriver()
    {
        await using var server = SilentServer.Start();
        var bot = Robot.Create("KukaBot", "KUKA");
        bot.ControlMode("online");
        bot.ConnectTimeout = TimeSpan.FromMilliseconds(300);
        var error = await Assert.ThrowsAsync<RobotConnectionException>(() => bot.ConnectAsync("127.0.0.1", server.Port).WaitAsync(Limit));
        Assert.Contains("machina_kuka_driver", error.Message, StringComparison.Ordinal);
        Assert.False(bot.IsConnected);
    }
}
