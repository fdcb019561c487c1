using System.Net;
using System.Net.Sockets;
using System.Text;
using Machina.Simulation;
using Machina.Simulation.UrScript;
using Machina.Tests.Support;

namespace Machina.Tests.Simulation.UrScript;

/// <summary>
/// What the scripts UR's clients upload (UR client library's external control program, ur_rtde's control script) need of the
/// twin, each written here as our own program: expressions over lines, array arithmetic, the manual's scoping rules, thread
/// handles of 0, blocking socket reads, and the force, freedrive, contact, gravity and payload functions.
/// </summary>
public class UrClientScriptTests
{
    private static readonly TimeSpan Timeout = TimeSpan.FromSeconds(15);

    private static IReadOnlyList<string> Messages(string program, UrTwinController? twin = null)
    {
        twin ??= new UrTwinController();
        using (twin)
        {
            UrProgramState state = twin.Run(program, CancellationToken.None);
            Assert.True(state == UrProgramState.Finished, twin.Error);
            return twin.Pendant.Lines;
        }
    }

    [Fact]
    public void Expressions_ContinueOverLinesAfterABinaryOperator()
    {
        IReadOnlyList<string> lines = Messages("""
            def prog():
              a = 1 +
                2 *
                3
              if a == 7 and
                 a > 6 or
                 False:
                textmsg("yes ", a)
              end
            end
            """);
        Assert.Equal(["yes 7"], lines);
    }

    [Fact]
    public void Arrays_ArithmeticElementByElement()
    {
        IReadOnlyList<string> lines = Messages("""
            def prog():
              q = [1, 2, 3]
              textmsg(q * 2, "")
              textmsg(-3 * q + [10, 10, 10], "")
              textmsg(q / 2, "")
              textmsg(-q, "")
              textmsg(q - [1, 1, 1] * 0.5, "")
            end
            """);
        Assert.Equal(["[2, 4, 6]", "[7, 4, 1]", "[0.5, 1, 1.5]", "[-1, -2, -3]", "[0.5, 1.5, 2.5]"], lines);
    }

    [Fact]
    public void Arrays_OfDifferentLengths_StopTheProgram()
    {
        using var twin = new UrTwinController();
        Assert.Equal(UrProgramState.Failed, twin.Run("def prog():\n  x = [1, 2] + [1, 2, 3]\nend\n", CancellationToken.None));
        Assert.Equal("Runtime error: line 2: '+' needs arrays of the same length, not 2 and 3", twin.Error);
    }

    [Fact]
    public void FreeVariables_InNestedFunctions_AreTheProgramsVariables_AndHandlesOfZeroAreNoThread()
    {
        IReadOnlyList<string> lines = Messages("""
            def prog():
              global running = False
              worker = 0
              def start():
                if not running:
                  running = True
                  worker = run job()
                end
              end
              def finish():
                join worker
                worker = 0
              end
              thread job():
                running = False
              end
              join worker
              kill worker
              start()
              finish()
              textmsg(running, worker)
            end
            """);
        Assert.Equal(["False0"], lines);
    }

    [Fact]
    public void ForceFreedriveContactGravityPayload_AcceptedAndApproximated()
    {
        var twin = new UrTwinController();
        Joints before = twin.Arm.Joints;
        IReadOnlyList<string> lines = Messages("""
            def prog():
              force_mode_set_damping(0.5)
              force_mode_set_gain_scaling(1.5)
              force_mode(p[0, 0, 0, 0, 0, 0], [0, 0, 1, 0, 0, 0], [0, 0, -10, 0, 0, 0], 2, [0.1, 0.1, 0.1, 0.3, 0.3, 0.3])
              textmsg("force ", 1)
              end_force_mode()
              freedrive_mode()
              freedrive_mode(freeAxes=[1, 1, 1, 0, 0, 0], feature=p[0, 0, 0, 0, 0, 0])
              end_freedrive_mode()
              textmsg("contact ", tool_contact(direction=get_actual_tcp_speed()))
              set_gravity([0, 9.82, 0])
              set_target_payload(1.5, [0, 0, 0.05], [0, 0, 0, 0, 0, 0], 0.5)
              zero_ftsensor()
              ft_rtde_input_enable(True, 0.2, [0, 0, 0], [0, 0, 0.01])
              textmsg(get_list_length([1, 2, 3]), get_joint_positions() == get_actual_joint_positions())
              textmsg("history ", get_actual_joint_positions_history(10) == get_actual_joint_positions())
              rtde_set_watchdog("input_int_register_0", 10, "stop")
              speedj([0, 0, 0, 0, 0, 0], 0, 0.002)
            end
            """, twin);
        Assert.Equal(["force 1", "contact 0", "3True", "history True"], lines);
        Assert.Equal(1.5, twin.Arm.PayloadKg);
        Assert.Equal([0, 9.82, 0], twin.Modes.Gravity);
        Assert.False(twin.Modes.ForceMode);
        Assert.False(twin.Modes.Freedrive);
        Assert.Empty(twin.Watchdog.Armed); // set, then removed as the program ended (UrSimWatchdogTests runs one out)
        Assert.Equal(before, twin.Arm.Joints); // nothing pushed the arm
    }

    [Theory]
    [InlineData("force_mode(p[0, 0, 0, 0, 0, 0], [0, 0, 1, 0, 0, 0], [0, 0, 0, 0, 0, 0], 4, [0.1, 0.1, 0.1, 0.3, 0.3, 0.3])", "force_mode: argument 'type' must be 1, 2 or 3, not 4")]
    [InlineData("force_mode(p[0, 0, 0, 0, 0, 0], [0, 0, 2, 0, 0, 0], [0, 0, 0, 0, 0, 0], 2, [0.1, 0.1, 0.1, 0.3, 0.3, 0.3])", "force_mode: the selection vector's elements must be 0 or 1")]
    [InlineData("force_mode_set_damping(1.5)", "force_mode_set_damping: argument 'damping' must be between 0 and 1, not 1.5")]
    [InlineData("set_gravity([0, 9.82])", "set_gravity: argument 'd' must be an array of 3 numbers, not an array of 2")]
    [InlineData("rtde_set_watchdog(\"input_int_register_0\", 10, \"halt\")", "rtde_set_watchdog: argument 'action' must be \"ignore\", \"pause\" or \"stop\", not \"halt\"")]
    [InlineData("optimovej([0, -1.57, 1.57, -1.57, -1.57, 0], a=1.4)", "optimovej: argument 'a' must be a fraction in (0, 1], not 1.4")]
    [InlineData("optimovel(p[0.3, -0.1, 0.4, 0, 3.14, 0], v=0)", "optimovel: argument 'v' must be a fraction in (0, 1], not 0")]
    [InlineData("direct_torque([0, 0, 0, 0, 0])", "direct_torque: argument 'torque' must be a pose or a list of 6 numbers, not an array of 5")]
    public void ControlFunctions_BadArguments_StopTheProgram(string call, string reason)
    {
        using var twin = new UrTwinController();
        Assert.Equal(UrProgramState.Failed, twin.Run($"def prog():\n  {call}\nend\n", CancellationToken.None));
        Assert.Equal("Runtime error: line 2: " + reason, twin.Error);
    }

    [Fact]
    public void Optimove_MovesAsMovejAndMovel_AtTheFractionsOfTheTwinsCapabilities()
    {
        using var twin = new UrTwinController();
        UrProgramState state = twin.Run("""
            def prog():
              q = get_actual_joint_positions()
              q[0] = 0.5
              optimovej(q, a=0.5, v=0.4)
              textmsg(get_actual_joint_positions()[0])
              start = get_actual_tcp_pose()
              optimovel(pose_trans(start, p[0.1, 0, 0, 0, 0, 0]), a=0.2, v=0.1)
              direct_torque([0, 0, 0, 0, 0, 0], friction_comp=False)
              textmsg(pose_dist(start, get_actual_tcp_pose()))
            end
            """, CancellationToken.None);
        Assert.True(state == UrProgramState.Finished, twin.Error);
        Assert.Equal("0.5", twin.Pendant.Lines[0]);
        Assert.Equal(0.1, double.Parse(twin.Pendant.Lines[^1], System.Globalization.CultureInfo.InvariantCulture), 6);
        // 0.5 rad at 0.4 × 180 °/s (the UR5e's joints) and 0.5 × 15 rad/s², then 0.1 m at 0.1 × 1 m/s and 0.2 × 10 m/s².
        double joint = Machina.Simulation.Twin.TwinMotion.TrapezoidSeconds(0.5, 0.4 * Math.PI, 7.5);
        double line = Machina.Simulation.Twin.TwinMotion.TrapezoidSeconds(0.1, 0.1, 2);
        Assert.Equal(joint + line, twin.Clock.Seconds, 6);
    }

    [Fact]
    public void RtdeControlScriptFunctions_AnswerAsAStandingArm()
    {
        var twin = new UrTwinController();
        IReadOnlyList<string> lines = Messages("""
            def prog():
              set_tcp(p[0, 0, 0.1, 0, 0, 0])
              set_payload(1.25, [0.01, 0.02, 0.03])
              textmsg(get_target_payload(), get_target_payload_cog())
              textmsg("offset ", get_tcp_offset())
              flange = get_actual_tool_flange_pose()
              textmsg("flange ", point_dist(pose_trans(flange, get_tcp_offset()), get_actual_tcp_pose()) < 1e-9)
              textmsg("waypoint ", pose_dist(get_target_waypoint(), get_actual_tcp_pose()) < 1e-9)
              textmsg("torques ", get_joint_torques())
              teach_mode()
              textmsg("freedrive ", get_freedrive_status())
              end_teach_mode()
              enable_external_ft_sensor(True, 0.2, [0, 0, 0], [0, 0, 0.01])
              start = get_actual_tcp_pose()
              servoc(pose_trans(start, p[0.05, 0, 0, 0, 0, 0]), a=1.2, v=0.25)
              textmsg("servoc ", point_dist(start, get_actual_tcp_pose()))
            end
            """, twin);
        Assert.Equal(["1.25[0.01, 0.02, 0.03]", "offset p[0, 0, 0.1, 0, 0, 0]", "flange True", "waypoint True",
            "torques [0, 0, 0, 0, 0, 0]", "freedrive 0", "servoc 0.05"], lines);
        Assert.False(twin.Modes.Freedrive);
    }

    [Fact]
    public void ProtectiveStop_HoldsTheProgramUntilReleased()
    {
        using var twin = new UrTwinController();
        Assert.True(twin.Start("def prog():\n  protective_stop()\n  textmsg(\"after\")\nend\n"));
        Assert.True(SpinWait.SpinUntil(() => twin.IsHeld, Timeout));
        Thread.Sleep(50);
        Assert.Empty(twin.Pendant.Lines);
        Assert.True(twin.Release());
        Assert.True(twin.WaitForEnd(Timeout));
        Assert.Equal(["after"], twin.Pendant.Lines);
    }

    [Fact]
    public void Assignment_ValueOnTheNextLine_BeforeThatLinesOwnStatement()
    {
        // As ur_rtde fills its control script's register offsets: the value goes after the comment's line end.
        IReadOnlyList<string> lines = Messages("""
            def prog():
                global a = # first offset
            0    global b = # second offset
            7    global c = 2
                d =
                  3
                textmsg(a, b + c + d)
                def scale(p, factor):
                  p[0] = p[0] * factor
                  p[5] = p[5] * factor
                  return p
                end
                textmsg(scale(p[0.1, 0.2, 0.3, 0, 0, 0.5], 2))
            end
            """);
        Assert.Equal(["012", "p[0.2, 0.2, 0.3, 0, 0, 1]"], lines);
    }

    [Fact]
    public void MoveC_ToJointPositions_GoesWhereThoseJointsPutTheTool()
    {
        using var twin = new UrTwinController();
        UrProgramState state = twin.Run("""
            def prog():
              movej([0, -1.57, 1.57, -1.57, -1.57, 0])
              via = get_inverse_kin(pose_trans(get_actual_tcp_pose(), p[0.05, 0.05, 0, 0, 0, 0]))
              to = get_inverse_kin(pose_trans(get_actual_tcp_pose(), p[0.1, 0, 0, 0, 0, 0]))
              expected = get_forward_kin(to)
              movec(via, to, a=1.2, v=0.25)
              textmsg(pose_dist(get_actual_tcp_pose(), expected) < 1e-6, "")
            end
            """, CancellationToken.None);
        Assert.True(state == UrProgramState.Finished, twin.Error);
        Assert.Equal(["True"], twin.Pendant.Lines);
    }

    [Fact]
    public async Task SocketRead_WithTimeoutZero_WaitsForTheData()
    {
        await using var controller = new VirtualUrController(new VirtualUrControllerOptions { InstantExecution = true });
        await controller.StartAsync();
        using var server = new TcpListener(IPAddress.Loopback, 0);
        server.Start();
        int port = ((IPEndPoint)server.LocalEndpoint).Port;
        using var upload = await UrSimClientInterfaceTests.ConnectAsync(controller.Port);
        await upload.GetStream().WriteAsync(Encoding.ASCII.GetBytes(
            $"def p():\n  socket_open(\"127.0.0.1\", {port}, \"rev\")\n  v = socket_read_binary_integer(2, \"rev\", 0)\n  socket_send_int(v[0] * 100 + v[2], \"rev\")\nend\n"));
        using var client = await server.AcceptTcpClientAsync().WaitAsync(Timeout);
        await Task.Delay(300); // longer than an immediate read: a timeout of 0 must not give up at once
        await WireInts.WriteAsync(client.GetStream(), [5, 7]);

        Assert.Equal(new[] { 207 }, await WireInts.ReadAsync(client.GetStream(), 1, Timeout));
        Assert.Empty(controller.Errors);
    }
}
