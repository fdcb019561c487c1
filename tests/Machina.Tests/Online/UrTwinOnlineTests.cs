using System.Collections.Concurrent;
using System.Net;
using System.Net.Sockets;
using System.Text;
using Machina.Simulation;
using Machina.Tests.Support;
using static Machina.Tests.Online.OnlineTestSupport;
using static Machina.Tests.Online.UrOnlineTestSupport;

namespace Machina.Tests.Online;

/// <summary>
/// The virtual UR that runs URScript (issue 26): with <see cref="VirtualUrControllerOptions.RunsScripts"/> the unchanged driver of
/// drivers/ur, filled and uploaded by the host as for a robot, runs on the interpreter; acknowledgements, RTDE progress and poses
/// come from what the script itself did.
/// </summary>
public class UrTwinOnlineTests
{
    private static readonly RobotModel Ur5e = RobotModels.Get("UR5e");

    private static VirtualUrControllerOptions Interpreted(bool instant = true) => new() { RunsScripts = true, InstantExecution = instant };

    [Fact]
    public async Task HelloRobot_OnTheInterpreter_SevenOfSevenInOrder_EndsWhereTheScriptMovedTheArm()
    {
        await using var controller = await StartUrAsync(Interpreted());
        Robot bot = await ConnectUrAsync(controller);
        var executed = new ConcurrentQueue<int>();
        bot.ActionExecuted += (_, e) => executed.Enqueue(e.LastAction.Id);
        try
        {
            ReferencePrograms.HelloRobot(bot);
            await bot.WaitForCompletionAsync().WaitAsync(Limit);
            await bot.FlushEventsAsync().WaitAsync(Limit);

            Assert.Equal([1, 2, 3, 4, 5, 6, 7], executed);
            // The wire carries 1e-6 rad: 90° arrives as 1.570796 rad.
            Joints end = controller.Twin!.Arm.Joints;
            Assert.True(end.IsSimilar(new Joints(0, 0, 0, 0, 90, 0), 0.001), end.ToString());
            Assert.Equal(7.0, controller.Twin.Io.GetNumber(Machina.Simulation.UrScript.UrIoBanks.OutputIntRegisters, 24)); // the driver's own progress register
            Assert.Contains("Machina driver 3.0.0 connected to 127.0.0.1", controller.PendantMessages);
            Assert.True(controller.IsProgramRunning);
            Assert.Equal(2u, controller.RuntimeState);
            Assert.Equal(1, controller.ScriptsReceived);
            Assert.StartsWith("def machina_ur_driver():", controller.LastScript, StringComparison.Ordinal);
            Assert.Empty(controller.Errors);
            Assert.Equal(6, controller.RequestsReceived); // what the driver read on its socket and acknowledged (ids 2 to 7: action 1 sends nothing)
        }
        finally
        {
            await bot.DisconnectAsync();
        }
    }

    [Fact]
    public async Task Stream_TenThousandActions_ThroughTheInterpretedDriver_EachOnceInOrder_RtdeFromItsMotion()
    {
        await using var controller = await StartUrAsync(Interpreted());
        Robot bot = await ConnectUrAsync(controller, b => { b.BlockSize = 100; b.PendingCount = 100; });
        var executed = new ConcurrentQueue<int>();
        bot.ActionExecuted += (_, e) => executed.Enqueue(e.LastAction.Id);
        try
        {
            bot.MoveTo(300, -300, 400);
            for (int i = 1; i < 10_000; i++)
            {
                bot.Move(i % 2 == 0 ? 10 : -10, 0, 0);
            }
            await bot.WaitForCompletionAsync().WaitAsync(TimeSpan.FromMinutes(3));
            await bot.FlushEventsAsync().WaitAsync(TimeSpan.FromMinutes(1));

            Assert.Equal(Enumerable.Range(1, 10_000), executed);
            Assert.Empty(controller.Errors);
            // RTDE, read by a client written from the guide: the pose the script's last movel reached and its progress registers.
            using var rtde = await GuideRtdeClient.ConnectAsync(controller.RtdePort);
            Assert.True(await rtde.NegotiateAsync());
            await rtde.SetupOutputsAsync(125, "actual_TCP_pose", "actual_q", "runtime_state", "output_int_register_24", "output_int_register_25");
            Assert.True(await rtde.StartAsync());
            var data = await rtde.ReadDataAsync();
            var pose = (double[])data["actual_TCP_pose"];
            Assert.True(new Vector(pose[0] * 1000, pose[1] * 1000, pose[2] * 1000).IsSimilar(new Vector(290, -300, 400), 1e-6), string.Join(", ", pose));
            var q = (double[])data["actual_q"];
            Joints joints = Joints.FromArray([.. q.Select(r => r * 180 / Math.PI)]);
            Assert.True(Ur5e.Kinematics.Forward(joints).Position.IsSimilar(new Vector(290, -300, 400), 1e-6));
            Assert.Equal((2L, 10_000L, 10_000L), ((long)data["runtime_state"], (long)data["output_int_register_24"], (long)data["output_int_register_25"]));
            Assert.Equal(10_000, controller.Twin!.Arm.Trace.Count(t => t.Kind == Machina.Simulation.Twin.TwinTraceKind.Motion));
        }
        finally
        {
            await bot.DisconnectAsync();
        }
    }

    [Fact]
    public async Task Script_WithoutAFinalLineBreak_RunsAtItsEnd()
    {
        await using var controller = await StartUrAsync(Interpreted());
        using var script = new TcpClient();
        await script.ConnectAsync(IPAddress.Loopback, controller.Port);
        await script.GetStream().WriteAsync(Encoding.ASCII.GetBytes("# a comment line first\ndef p():\n  write_output_integer_register(3, 42)\nend"));

        using var rtde = await GuideRtdeClient.ConnectAsync(controller.RtdePort);
        Assert.True(await rtde.NegotiateAsync());
        await rtde.SetupOutputsAsync(125, "output_int_register_3");
        Assert.True(await rtde.StartAsync());
        long value = 0;
        for (int i = 0; i < 5_000 && value != 42; i++)
        {
            value = (long)(await rtde.ReadDataAsync())["output_int_register_3"];
        }

        Assert.Equal(42, value);
        Assert.Equal("def p():\n  write_output_integer_register(3, 42)\nend", controller.LastScript);
        Assert.Equal(1, controller.ScriptsReceived);
        Assert.Empty(controller.Errors);
        Assert.True(script.Connected); // the connection was not closed to make it run
    }

    [Fact]
    public async Task Script_WithAnUnknownFunction_RefusedWithItsLine_NothingRuns_TheRunningProgramGoesOn()
    {
        await using var controller = await StartUrAsync(Interpreted(instant: false));
        using var script = new TcpClient();
        await script.ConnectAsync(IPAddress.Loopback, controller.Port);
        NetworkStream stream = script.GetStream();
        await stream.WriteAsync(Encoding.ASCII.GetBytes("def waiting():\n  textmsg(\"waiting\")\n  sleep(3600)\nend\n"));
        await EventuallyAsync(() => controller.PendantMessages.Contains("waiting"), "the first program to run");

        await stream.WriteAsync(Encoding.ASCII.GetBytes("def bad():\n  textmsg(\"never\")\n  no_such_function(2)\nend\n"));
        await EventuallyAsync(() => controller.Errors.Count == 1, "the refusal");

        Assert.Equal("Compile error: line 3: unknown function 'no_such_function'", controller.Errors[0]);
        Assert.DoesNotContain("never", controller.PendantMessages);
        Assert.True(controller.IsProgramRunning);
        Assert.Equal("PLAYING waiting", await DashboardAsync(controller, "programState"));
        Assert.Equal(2, controller.ScriptsReceived);
    }

    [Fact]
    public async Task Robot_UnreachableMove_TheScriptStopsWithTheControllerReason_HostReportsTheActionFailed()
    {
        await using var controller = await StartUrAsync(Interpreted());
        var failed = new TaskCompletionSource<ActionFailedArgs>(TaskCreationOptions.RunContinuationsAsynchronously);
        var executed = new ConcurrentQueue<int>();
        Robot bot = await ConnectUrAsync(controller, b =>
        {
            b.ActionExecuted += (_, e) => executed.Enqueue(e.LastAction.Id);
            b.ActionFailed += (_, e) => failed.TrySetResult(e);
        });
        try
        {
            Vector at = bot.GetExecutedState().Position!.Value;
            bot.SpeedTo(100);
            bot.MoveTo(at.X, at.Y, at.Z - 20);
            Assert.True(bot.WaitForCompletion(Limit));
            // The failure reports the arm where RTDE last showed it; "executed" comes from the script, RTDE's samples on their own
            // clock: under load the last one can still be the arm's last millimetre. Wait (bounded) until RTDE shows it stopped.
            Vector stop = at + new Vector(0, 0, -20);
            using (var seen = new CancellationTokenSource(Limit))
            {
                while (!(bot.GetMotionState()?.Position is Vector live && live.IsSimilar(stop, 0.01)))
                {
                    await Task.Delay(5, seen.Token);
                }
            }

            // Issued together (one issue lock): a failure this quick cannot come between them, so the second is cancelled, never issued after.
            bot.Do(FormattableString.Invariant($"MoveTo(2000, 0, 500); MoveTo({at.X}, {at.Y}, {at.Z});"));
            ActionFailedArgs e = await failed.Task.WaitAsync(Limit);
            await Assert.ThrowsAsync<ActionFailedException>(() => bot.WaitForCompletionAsync().WaitAsync(Limit));

            Assert.Equal(3, e.Action.Id);
            int line = 1 + Array.FindIndex(controller.LastScript!.Split('\n'), l => l.Contains("movel(pose_of", StringComparison.Ordinal));
            Assert.Equal($"movel: no inverse kinematics solution: the target pose is out of reach (driver script line {line})", e.Reason);
            Assert.Equal([4], e.CancelledActions.Select(a => a.Id));
            Assert.True(e.Position is Vector stoppedAt && stoppedAt.IsSimilar(stop, 0.1), e.Position?.ToString());
            Assert.Equal([1, 2], executed);
            Assert.Equal(1u, controller.RuntimeState);
            Assert.Equal("movel: no inverse kinematics solution: the target pose is out of reach", controller.LastRuntimeException);
            Assert.Contains(controller.Errors, m => m.StartsWith("Runtime error: line ", StringComparison.Ordinal));
            Assert.Equal(2.0, controller.Twin!.Io.GetNumber(Machina.Simulation.UrScript.UrIoBanks.OutputIntRegisters, 24));
        }
        finally
        {
            await bot.DisconnectAsync();
        }
    }

    private static async Task<string> DashboardAsync(VirtualUrController controller, string command)
    {
        using var client = new TcpClient();
        await client.ConnectAsync(IPAddress.Loopback, controller.DashboardPort);
        using var reader = new StreamReader(client.GetStream(), Encoding.ASCII);
        await reader.ReadLineAsync().WaitAsync(Limit);
        await client.GetStream().WriteAsync(Encoding.ASCII.GetBytes(command + "\n"));
        return (await reader.ReadLineAsync().WaitAsync(Limit))!;
    }
}
