using System.Net;
using System.Net.Sockets;
using System.Text;
using Machina.Simulation;
using Machina.Tests.Support;

namespace Machina.Tests.Simulation;

/// <summary>
/// The virtual UR's driver connection writes through the controller's network stack (<c>TwinHeldOutbox</c>, issue 45): what the
/// program's own thread sends there is held while it runs and goes out, in order and whole, when it is about to wait (a socket
/// read that must wait, a connect, a sleep, a join) or ends. The host's link then wakes once per burst, not once per value.
/// </summary>
public class VirtualUrHeldSendTests
{
    private static readonly TimeSpan Timeout = TimeSpan.FromSeconds(15);

    private static string Script(int driverPort, int otherPort) => string.Join('\n',
        "def held():",
        "  socket_open(\"127.0.0.1\", " + driverPort.ToString(System.Globalization.CultureInfo.InvariantCulture) + ", \"host\")",
        "  socket_send_int(7, \"host\")",
        "  socket_send_int(8, \"host\")",
        // The route of this connect is asked on the program's thread before it waits for the connect: the test looks there.
        "  socket_open(\"127.0.0.1\", " + otherPort.ToString(System.Globalization.CultureInfo.InvariantCulture) + ", \"other\")",
        "  h = socket_read_binary_integer(1, \"host\", 5)",
        "  socket_send_int(h[1] + 1, \"host\")",
        "  socket_read_binary_integer(1, \"host\", 5)",
        "end",
        "");

    [Fact]
    public async Task ProgramSendsThenRuns_NothingLeavesUntilItWaits_ThenEverythingInOrder()
    {
        using var driverServer = new TcpListener(IPAddress.Loopback, 0);
        using var otherServer = new TcpListener(IPAddress.Loopback, 0);
        driverServer.Start();
        otherServer.Start();
        int driverPort = ((IPEndPoint)driverServer.LocalEndpoint).Port;
        int otherPort = ((IPEndPoint)otherServer.LocalEndpoint).Port;
        Socket? driver = null;
        bool? arrivedWhileRunning = null;
        await using var controller = new VirtualUrController(new VirtualUrControllerOptions
        {
            RunsScripts = true,
            InstantExecution = true,
            OutboundRoute = to =>
            {
                if (to.Port == otherPort)
                {
                    // On the program's thread, after its two sends and before any wait: held, so nothing is readable (the
                    // sends of a controller without the stack's hold were in this socket's buffer before this call).
                    driver = driverServer.AcceptSocket();
                    arrivedWhileRunning = driver.Poll(300_000, SelectMode.SelectRead);
                }
                return to;
            },
        });
        await controller.StartAsync();
        using var script = new TcpClient();
        await script.ConnectAsync(IPAddress.Loopback, controller.Port);
        await script.GetStream().WriteAsync(Encoding.ASCII.GetBytes(Script(driverPort, otherPort)));
        using Socket other = await otherServer.AcceptSocketAsync().WaitAsync(Timeout);

        Assert.False(arrivedWhileRunning);
        using var stream = new NetworkStream(driver!, ownsSocket: true);
        // The program then waits in its read: both values go out, in order.
        Assert.Equal(new[] { 7, 8 }, await WireInts.ReadAsync(stream, 2, Timeout));
        await WireInts.WriteAsync(stream, [41]);
        Assert.Equal(new[] { 42 }, await WireInts.ReadAsync(stream, 1, Timeout));
    }
}
