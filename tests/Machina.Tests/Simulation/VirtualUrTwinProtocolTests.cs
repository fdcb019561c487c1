using System.Net;
using System.Net.Sockets;
using System.Text;
using Machina.Simulation;
using Machina.Tests.Support;

namespace Machina.Tests.Simulation;

/// <summary>
/// The virtual UR that runs scripts speaks whatever protocol the uploaded script speaks. Here a small script written for this
/// test from the original Machina.NET protocol (spec online §7.2-7.3: big-endian int32, 1e-4 m and 1e-4 rad, a full pose first,
/// then [id, code, parameters] answered by the id) is uploaded the way the original host does: the definition, then its call
/// line with no line break after it.
/// </summary>
public class VirtualUrTwinProtocolTests
{
    private static readonly TimeSpan Timeout = TimeSpan.FromSeconds(15);

    private static string OriginalStyleDriver(int port) => string.Join('\n',
        "def original_style():",
        "  socket_open(\"127.0.0.1\", " + port.ToString(System.Globalization.CultureInfo.InvariantCulture) + ", \"host\")",
        "  speed = 0.02",
        "  tcp = get_actual_tcp_pose()",
        "  q = get_actual_joint_positions()",
        "  socket_send_int(-54, \"host\")",
        "  k = 0",
        "  while k < 6:",
        "    socket_send_int(floor(tcp[k] * 10000 + 0.5), \"host\")",
        "    k = k + 1",
        "  end",
        "  k = 0",
        "  while k < 6:",
        "    socket_send_int(floor(q[k] * 10000 + 0.5), \"host\")",
        "    k = k + 1",
        "  end",
        "  socket_send_int(-2147483648, \"host\")",
        "  while True:",
        "    h = socket_read_binary_integer(2, \"host\", 2)",
        "    if h[0] == 2:",
        "      if h[2] == 1:",
        "        v = socket_read_binary_integer(6, \"host\", 2)",
        "        movel(p[v[1] / 10000, v[2] / 10000, v[3] / 10000, v[4] / 10000, v[5] / 10000, v[6] / 10000], a=1.2, v=speed)",
        "      elif h[2] == 15:",
        "        speed = socket_read_binary_integer(1, \"host\", 2)[1] / 10000",
        "      end",
        "      socket_send_int(h[1], \"host\")",
        "    end",
        "  end",
        "end",
        "",
        "# start it",
        "original_style()");

    [Fact]
    public async Task OriginalStyleDriver_UploadedWithoutAFinalLineBreak_ConnectsBackSendsThePoseAndRunsMoves()
    {
        await using var controller = new VirtualUrController(new VirtualUrControllerOptions { RunsScripts = true, InstantExecution = true });
        await controller.StartAsync();
        using var server = new TcpListener(IPAddress.Loopback, 0);
        server.Start();
        using var script = new TcpClient();
        await script.ConnectAsync(IPAddress.Loopback, controller.Port);
        string upload = OriginalStyleDriver(((IPEndPoint)server.LocalEndpoint).Port);
        Assert.False(upload.EndsWith('\n'));
        await script.GetStream().WriteAsync(Encoding.ASCII.GetBytes(upload));
        using var driver = await server.AcceptTcpClientAsync().WaitAsync(Timeout);
        NetworkStream stream = driver.GetStream();

        int[] pose = await WireInts.ReadAsync(stream, 14, Timeout);
        Assert.Equal((-54, int.MinValue), (pose[0], pose[13]));
        Assert.Equal(new[] { 0, -15708, -15708, -15708, 15708, 0 }, pose[7..13]); // the UR5e's start joints in 1e-4 rad
        // Speed 50 mm/s, then a move to (400, 0, 300) mm with the tool down (rotation vector [π, 0, 0]).
        await WireInts.WriteAsync(stream, [1, 15, 500, 2, 1, 4000, 0, 3000, 31416, 0, 0]);

        Assert.Equal(new[] { 1, 2 }, await WireInts.ReadAsync(stream, 2, Timeout));
        Pose tcp = controller.Twin!.Arm.Tcp;
        Assert.True(tcp.Position.IsSimilar(new Vector(400, 0, 300), 1e-6), tcp.Position.ToString());
        Assert.True(controller.IsProgramRunning);
        Assert.Equal(1, controller.ScriptsReceived);
        Assert.Empty(controller.Errors);
    }
}
