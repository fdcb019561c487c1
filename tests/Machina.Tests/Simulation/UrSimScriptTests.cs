using System.Net;
using System.Net.Sockets;
using System.Text;
using Machina.Simulation;
using Machina.Tests.Support;

namespace Machina.Tests.Simulation;

/// <summary>URScript as the clients of a UR upload it, run on the virtual UR through its script port.</summary>
public class UrSimScriptTests
{
    private static readonly TimeSpan Timeout = TimeSpan.FromSeconds(15);

    [Fact]
    public async Task SocketSendInt_OfAFloat_SendsItTruncated_AsTheOriginalDriverNeeds()
    {
        await using var controller = new VirtualUrController(new VirtualUrControllerOptions { InstantExecution = true });
        await controller.StartAsync();
        using var server = new TcpListener(IPAddress.Loopback, 0);
        server.Start();
        int port = ((IPEndPoint)server.LocalEndpoint).Port;
        using var upload = await UrSimClientInterfaceTests.ConnectAsync(controller.Port);
        await upload.GetStream().WriteAsync(Encoding.ASCII.GetBytes(
            $"def p():\n  socket_open(\"127.0.0.1\", {port})\n  FACTOR_M = 10000\n  socket_send_int(FACTOR_M * -2.221441)\n  socket_send_int(2.7)\n  socket_send_int(7)\nend\n"));
        using var driver = await server.AcceptTcpClientAsync().WaitAsync(Timeout);

        Assert.Equal(new[] { -22214, 2, 7 }, await WireInts.ReadAsync(driver.GetStream(), 3, Timeout));
        Assert.Empty(controller.Errors);
    }

    [Fact]
    public async Task ClientLibraryScript_StatementsOverLines_CriticalSections_SpeedJ_Run()
    {
        await using var controller = new VirtualUrController(new VirtualUrControllerOptions { InstantExecution = true });
        await controller.StartAsync();
        double j1 = controller.State.Joints.J1;
        using var upload = await UrSimClientInterfaceTests.ConnectAsync(controller.Port);
        await upload.GetStream().WriteAsync(Encoding.ASCII.GetBytes(
            "def p():\n  enter_critical\n  x = [1,\n    2]\n  write_output_integer_register(1, x[0] +\n     x[1])\n  exit_critical\n" +
            "  speedj([0.1, 0, 0, 0, 0, 0], 0.5, 1.0)\n  s = get_target_joint_speeds()\n  write_output_integer_register(2, 7 + s[0])\nend\n"));

        await OnlineWait.UntilAsync(() => controller.Twin.Io.GetNumber(Machina.Simulation.UrScript.UrIoBanks.OutputIntRegisters, 2) == 7, "the program to end");
        Assert.Equal(3, controller.Twin.Io.GetNumber(Machina.Simulation.UrScript.UrIoBanks.OutputIntRegisters, 1));
        Assert.Equal(j1 + 0.09 * 180 / Math.PI, controller.State.Joints.J1, 9); // 0.2 s up to 0.1 rad/s at 0.5 rad/s², then 0.8 s at it
        Assert.Empty(controller.Errors);
    }
}
