using System.Net;
using System.Net.Sockets;
using System.Text;
using Machina.Simulation;
using static Machina.Tests.Simulation.RawAbbClient;

namespace Machina.Tests.Simulation;

/// <summary>
/// The twins' ports against hostile clients (issue 40): each script connection of the UR twin has its own intake, a dashboard
/// line has a length cap, and text from the wire reaches the pendant printable.
/// </summary>
public sealed class NetworkIntakeTests
{
    [Theory]
    [InlineData(false)]
    [InlineData(true)]
    public async Task UrScriptPort_ASecondClientsUnfinishedBytes_DoNotJoinTheHostsProgram(bool primaryInterface)
    {
        await using var controller = new VirtualUrController(new VirtualUrControllerOptions { InstantExecution = true, PrimaryPort = 0 });
        await controller.StartAsync();
        int port = primaryInterface ? controller.PrimaryPort : controller.Port;
        using var stranger = new TcpClient();
        await stranger.ConnectAsync(IPAddress.Loopback, port);
        // A complete line (seen as a program), then three bytes without their line break, in one write.
        await stranger.GetStream().WriteAsync(Encoding.ASCII.GetBytes("textmsg(\"stranger\")\ntex"));
        await WaitUntilAsync(() => controller.ScriptsReceived == 1, "the stranger's line to arrive");

        const string program = "def hello():\n  textmsg(\"host\")\nend\n";
        using var host = new TcpClient();
        await host.ConnectAsync(IPAddress.Loopback, port);
        await host.GetStream().WriteAsync(Encoding.ASCII.GetBytes(program));
        try
        {
            await WaitUntilAsync(() => controller.PendantMessages.Contains("host"), "the host's program to run");
        }
        catch (TimeoutException ex)
        {
            // Say what the twin did instead, so that a failure names its cause.
            throw new TimeoutException($"{ex.Message}; scripts received {controller.ScriptsReceived}, pendant [{string.Join(" | ", controller.PendantMessages)}], "
                + $"errors [{string.Join(" | ", controller.Errors)}], last script {controller.LastScript}", ex);
        }

        Assert.Empty(controller.Errors);
        Assert.Equal(2, controller.ScriptsReceived);
        Assert.Equal(program, controller.LastScript);
    }

    [Fact]
    public async Task UrDashboard_ALineLongerThanTheCap_RefusedAndClosed_TheServerServesOn()
    {
        await using var controller = new VirtualUrController(new VirtualUrControllerOptions { InstantExecution = true });
        await controller.StartAsync();
        using (var flood = new TcpClient())
        {
            await flood.ConnectAsync(IPAddress.Loopback, controller.DashboardPort);
            NetworkStream stream = flood.GetStream();
            await ReadLineAsync(stream); // the greeting
            byte[] chunk = Encoding.ASCII.GetBytes(new string('a', 64 * 1024));
            try
            {
                for (int i = 0; i < 16; i++)
                {
                    await stream.WriteAsync(chunk); // 1 MiB, no line break
                }
            }
            catch (IOException)
            {
                // The server closed the connection while the client still wrote: what the test wants.
            }
            Assert.True(await ClosedAsync(stream), "the dashboard server to close a connection whose line passed its cap");
        }

        Assert.DoesNotContain(controller.DashboardCommands, c => c.Length > VirtualUrController.MaxDashboardLine);
        using var next = new TcpClient();
        await next.ConnectAsync(IPAddress.Loopback, controller.DashboardPort);
        await ReadLineAsync(next.GetStream());
        await next.GetStream().WriteAsync(Encoding.ASCII.GetBytes(new string(' ', VirtualUrController.MaxDashboardLine - 9) + "robotmode\r\n"));
        Assert.StartsWith("Robotmode: ", await ReadLineAsync(next.GetStream()), StringComparison.Ordinal);
    }

    [Fact]
    public async Task AbbTwin_EscapeCodesFromTheWire_ReachThePendantPrintable()
    {
        await using var controller = new VirtualAbbController(new VirtualAbbControllerOptions { InstantExecution = true, Model = null });
        await controller.StartAsync();
        using var client = await RawAbbClient.ConnectAsync(controller.Port);
        await client.ReadHandshakeAsync();

        // Not a number: the driver writes the token on the pendant (TPWrite) and complains.
        await client.SendAsync("@1 \u001b[2J\u001b[31mowned\u0007 1;");
        await WaitUntilAsync(() => controller.PendantMessages.Any(m => m.Contains("owned", StringComparison.Ordinal)), "the token on the pendant");

        Assert.Contains("\\x1b[2J\\x1b[31mowned\\x07", controller.PendantMessages);
        Assert.DoesNotContain(controller.PendantMessages, m => m.Any(char.IsControl));
    }

    private static async Task<string> ReadLineAsync(NetworkStream stream)
    {
        using var cts = new CancellationTokenSource(RawAbbClient.Timeout);
        var line = new StringBuilder();
        var one = new byte[1];
        while (await stream.ReadAsync(one, cts.Token) == 1 && one[0] != '\n')
        {
            line.Append((char)one[0]);
        }
        return line.ToString();
    }

    private static async Task<bool> ClosedAsync(NetworkStream stream)
    {
        using var cts = new CancellationTokenSource(RawAbbClient.Timeout);
        var buffer = new byte[4096];
        try
        {
            while (await stream.ReadAsync(buffer, cts.Token) > 0)
            {
            }
            return true;
        }
        catch (IOException)
        {
            return true;
        }
        catch (OperationCanceledException)
        {
            return false;
        }
    }
}
