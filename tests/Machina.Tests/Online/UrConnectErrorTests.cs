using System.Net;
using System.Net.Sockets;

namespace Machina.Tests.Online;

/// <summary>
/// Connecting a UR where nothing listens (issue 46: <c>Connect()</c> on a UR): a <see cref="MachinaException"/> a program can catch,
/// naming only the address and port the user gave (not the RTDE port Machina derives from it) and what to pass.
/// </summary>
public class UrConnectErrorTests
{
    [Fact]
    public void Connect_NothingListens_NamesTheGivenPortAndWhatToPass()
    {
        int port = ClosedPort();
        var bot = Robot.Create("Port", "UR");
        bot.ControlMode("online");
        bot.ConnectTimeout = TimeSpan.FromSeconds(5);

        MachinaException e = Assert.ThrowsAny<MachinaException>(() => bot.Connect("127.0.0.1", port));

        string given = port.ToString(System.Globalization.CultureInfo.InvariantCulture);
        string rtde = (port + 1).ToString(System.Globalization.CultureInfo.InvariantCulture);
        Assert.StartsWith($"Could not connect to a UR controller at 127.0.0.1, port {given} (", e.Message, StringComparison.Ordinal);
        Assert.EndsWith("Pass Connect the controller's address and its script port: Connect(\"192.168.1.10\", 30003) for a real UR "
            + "(or URSim) at that address, or the port \"machina sim ur\" printed for a virtual one.", e.Message, StringComparison.Ordinal);
        Assert.DoesNotContain(rtde, e.Message, StringComparison.Ordinal);
        Assert.False(bot.IsConnected);
    }

    /// <summary>A loopback port the OS just gave out and that nothing listens on any more (nor, most likely, on the next one).</summary>
    private static int ClosedPort()
    {
        var listener = new TcpListener(IPAddress.Loopback, 0);
        listener.Start();
        int port = ((IPEndPoint)listener.LocalEndpoint).Port;
        listener.Stop();
        return port;
    }
}
