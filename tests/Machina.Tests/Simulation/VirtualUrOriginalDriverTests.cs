using Machina.Simulation;
using Machina.Tests.Support;

namespace Machina.Tests.Simulation;

/// <summary>
/// The original Machina.NET driver protocol (spec online §7) on the virtual UR: a driver written here from the spec, uploaded
/// as the original host uploads it (a call line after its end and no final line break), runs on the interpreter and streams.
/// </summary>
public class VirtualUrOriginalDriverTests
{
    private static readonly TimeSpan Timeout = TimeSpan.FromSeconds(15);

    /// <summary>A driver of the original protocol: full pose on connect, then [id, code, params…] in, the id out after each.</summary>
    private static string OriginalDriver(int port) => $$"""
        def machina_ur_driver():
          MACHINA_DRIVER_VERSION = "1.2.0"
          HOSTNAME = "127.0.0.1"
          PORT = {{port}}
          FACTOR_M = 10000
          FACTOR_RAD = 10000
          FACTOR_SEC = 1000
          RES_FULL_POSE = -54
          RES_END = -2147483648
          speed = 0.02
          acceleration = 0.2
          joint_speed = 0.35
          joint_acceleration = 0.7
          blend = 0

          def send_full_pose():
            tcp = get_actual_tcp_pose()
            q = get_actual_joint_positions()
            socket_send_int(RES_FULL_POSE)
            i = 0
            while i < 6:
              socket_send_int(floor(tcp[i] * FACTOR_M))
              i = i + 1
            end
            i = 0
            while i < 6:
              socket_send_int(floor(q[i] * FACTOR_RAD))
              i = i + 1
            end
            socket_send_int(RES_END)
          end

          socket_open(HOSTNAME, PORT)
          textmsg("Started Machina driver")
          send_full_pose()
          while True:
            header = socket_read_binary_integer(2, "socket_0", 2)
            if header[0] == 0:
              # a timeout: nothing to do (a block of only a comment, as in the original driver)
            elif header[0] == 2:
              id = header[1]
              code = header[2]
              if code == 1:
                x = socket_read_binary_integer(6)
                movel(p[x[1] / FACTOR_M, x[2] / FACTOR_M, x[3] / FACTOR_M, x[4] / FACTOR_RAD, x[5] / FACTOR_RAD, x[6] / FACTOR_RAD], a=acceleration, v=speed, t=0, r=blend)
              elif code == 2:
                x = socket_read_binary_integer(6)
                movej(p[x[1] / FACTOR_M, x[2] / FACTOR_M, x[3] / FACTOR_M, x[4] / FACTOR_RAD, x[5] / FACTOR_RAD, x[6] / FACTOR_RAD], a=joint_acceleration, v=joint_speed, t=0, r=blend)
              elif code == 3:
                x = socket_read_binary_integer(6)
                movej([x[1] / FACTOR_RAD, x[2] / FACTOR_RAD, x[3] / FACTOR_RAD, x[4] / FACTOR_RAD, x[5] / FACTOR_RAD, x[6] / FACTOR_RAD], a=joint_acceleration, v=joint_speed, t=0, r=blend)
              elif code == 8:
                x = socket_read_binary_integer(1)
                blend = x[1] / FACTOR_M
              elif code == 12:
                x = socket_read_binary_integer(7)
                set_tcp(p[x[1] / FACTOR_M, x[2] / FACTOR_M, x[3] / FACTOR_M, x[4] / FACTOR_RAD, x[5] / FACTOR_RAD, x[6] / FACTOR_RAD])
                set_payload(x[7] / 1000)
              elif code == 15:
                x = socket_read_binary_integer(1)
                speed = x[1] / FACTOR_M
                joint_speed = 1000 * d2r(speed)
              elif code == 9:
                x = socket_read_binary_integer(1)
                sleep(x[1] / FACTOR_SEC)
              elif code == 13:
                x = socket_read_binary_integer(3)
                if x[3] != 0:
                  set_tool_digital_out(x[1], x[2] != 0)
                else:
                  set_standard_digital_out(x[1], x[2] != 0)
                end
              end
              socket_send_int(id)
            else:
              textmsg("Incorrectly formatted buffer")
            end
          end
        end


        # Kickstart the driver
        machina_ur_driver()
        """;

    [Fact]
    public async Task OriginalDriver_UploadedWithoutAFinalLineBreak_ConnectsSendsItsPoseAndStreams()
    {
        await using var controller = new VirtualUrController(new VirtualUrControllerOptions { InstantExecution = true });
        await controller.StartAsync();
        Vector start = controller.State.Position;
        using var server = new System.Net.Sockets.TcpListener(System.Net.IPAddress.Loopback, 0);
        server.Start();
        int port = ((System.Net.IPEndPoint)server.LocalEndpoint).Port;
        string script = OriginalDriver(port);
        Assert.EndsWith("machina_ur_driver()", script, StringComparison.Ordinal); // no line break after the call, as the original host sends it

        using var upload = new System.Net.Sockets.TcpClient();
        await upload.ConnectAsync(System.Net.IPAddress.Loopback, controller.Port);
        await upload.GetStream().WriteAsync(System.Text.Encoding.ASCII.GetBytes(script));
        using var driver = await server.AcceptTcpClientAsync().WaitAsync(Timeout);
        server.Stop();
        var stream = driver.GetStream();

        // Full pose: -54, X Y Z (1e-4 m), RX RY RZ (1e-4 rad), J1..J6 (1e-4 rad), end marker.
        int[] pose = await WireInts.ReadAsync(stream, 14, Timeout);
        Assert.Equal(-54, pose[0]);
        Assert.Equal(int.MinValue, pose[13]);
        // floor() of the script's float product: within one unit of the same product made here.
        Assert.InRange(pose[1], Math.Floor(start.X * 10) - 1, Math.Floor(start.X * 10) + 1);
        Assert.InRange(pose[2], Math.Floor(start.Y * 10) - 1, Math.Floor(start.Y * 10) + 1);
        Assert.InRange(pose[3], Math.Floor(start.Z * 10) - 1, Math.Floor(start.Z * 10) + 1);
        double j2 = controller.State.Joints.J2 * Math.PI / 180 * 10_000;
        Assert.InRange(pose[8], Math.Floor(j2) - 1, Math.Floor(j2) + 1);

        // As the original host streams: a move 10 mm down from the pose it was sent, a digital output, a wait.
        await WireInts.WriteAsync(stream, [1, 1, pose[1], pose[2], pose[3] - 100, pose[4], pose[5], pose[6], 2, 13, 1, 1, 0, 3, 9, 10]);
        Assert.Equal(new[] { 1, 2, 3 }, await WireInts.ReadAsync(stream, 3, Timeout));

        Assert.True(controller.State.Position.IsSimilar(new Vector(pose[1] / 10.0, pose[2] / 10.0, pose[3] / 10.0 - 10), 1e-4), controller.State.Position.ToString());
        Assert.True(controller.State.DigitalOutputs["1"]);
        Assert.Equal(new[] { 1, 2, 3 }, controller.ExecutedIds);
        Assert.Contains("Started Machina driver", controller.PendantMessages);
        Assert.Equal(1, controller.ScriptsReceived); // the call line belongs to the program: nothing replaced it
        Assert.True(controller.IsProgramRunning);
        Assert.Empty(controller.Errors);
    }

    [Fact]
    public async Task OriginalHost_OnAUrSim_PowersOnUploadsOnTheRealtimePortStreamsAndStops()
    {
        await using var controller = new VirtualUrController(new VirtualUrControllerOptions { InstantExecution = true, StartsPoweredOff = true, RealtimePort = 0 });
        await controller.StartAsync();
        using (var dashboard = new System.Net.Sockets.TcpClient())
        {
            // A UR fresh from boot (URSim): the user powers it on and releases the brakes before the host connects.
            await dashboard.ConnectAsync(System.Net.IPAddress.Loopback, controller.DashboardPort);
            var lines = new StreamReader(dashboard.GetStream(), System.Text.Encoding.ASCII);
            await lines.ReadLineAsync().WaitAsync(Timeout);
            foreach (string command in (string[])["power on", "brake release"])
            {
                await dashboard.GetStream().WriteAsync(System.Text.Encoding.ASCII.GetBytes(command + "\n"));
                await lines.ReadLineAsync().WaitAsync(Timeout);
            }
        }
        using var server = new System.Net.Sockets.TcpListener(System.Net.IPAddress.Loopback, 0);
        server.Start();
        int port = ((System.Net.IPEndPoint)server.LocalEndpoint).Port;

        // The original host uploads on the real-time port (30003 on a robot), without a final line break.
        using var upload = new System.Net.Sockets.TcpClient();
        await upload.ConnectAsync(System.Net.IPAddress.Loopback, controller.RealtimePort);
        await upload.GetStream().WriteAsync(System.Text.Encoding.ASCII.GetBytes(OriginalDriver(port)));
        using var driver = await server.AcceptTcpClientAsync().WaitAsync(Timeout);
        server.Stop();
        var stream = driver.GetStream();
        Assert.Equal(-54, (await WireInts.ReadAsync(stream, 14, Timeout))[0]);

        // The original host's bytes (spec online §7.4): Speed 100 mm/s, a Translation to (400, -100, 400) mm with the tool
        // down (rotation vector (0, pi, 0)), Axes (0, -90, 90, -90, -90, 0) deg, AttachTool 100 mm along z and 1.5 kg, then a
        // joint-interpolated Translation (MOVEJ_P) to (300, 200, 300) mm of the new tool.
        const int Down = 31416; // pi in 1e-4 rad
        int deg90 = (int)Math.Round(Math.PI / 2 * 10_000);
        await WireInts.WriteAsync(stream, [
            1, 15, 1000,
            2, 1, 4000, -1000, 4000, 0, Down, 0,
            3, 3, 0, -deg90, deg90, -deg90, -deg90, 0,
            4, 12, 0, 0, 1000, 0, 0, 0, 1500,
            5, 2, 3000, 2000, 3000, 0, Down, 0]);
        int[] acks = await WireInts.ReadAsync(stream, 5, Timeout).ContinueWith(read => read.IsCompletedSuccessfully ? read.Result : [], TaskScheduler.Default);
        Assert.True(acks.SequenceEqual([1, 2, 3, 4, 5]), string.Join("; ", controller.Errors));
        Assert.True(controller.State.Position.IsSimilar(new Vector(300, 200, 300), 1e-3), controller.State.Position.ToString());
        Assert.Equal(1.5, controller.Twin.Arm.PayloadKg);

        // Disconnect: the host uploads its stop program on the same connection; it replaces the driver and runs.
        await upload.GetStream().WriteAsync(System.Text.Encoding.ASCII.GetBytes("def machina_stop():\n  textmsg(\"Stopping\")\nend\n"));
        await OnlineWait.UntilAsync(() => controller.PendantMessages.Contains("Stopping") && !controller.IsProgramRunning, "the stop program to run");
        Assert.Equal(2, controller.ScriptsReceived);
        Assert.Empty(controller.Errors);
    }
}
