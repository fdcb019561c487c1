using System.Net;
using System.Net.Sockets;
using System.Text;
using Machina.Simulation;
using Machina.Tests.Support;

namespace Machina.Tests.Simulation;

/// <summary>The virtual UR's script ports as a raw client sees them: which scripts it runs, and the int protocol it speaks.</summary>
public class VirtualUrControllerTests
{
    private static readonly TimeSpan Timeout = TimeSpan.FromSeconds(15);

    /// <summary>Our driver as the original Machina.NET host uploads a driver: a call line after its end, and no final line break.</summary>
    private static string UploadedTheOriginalWay(int port) =>
        UrDriverScript.For("127.0.0.1", port, instance: 77).TrimEnd('\n') + "\n\n\n# Kickstart the driver\nmachina_ur_driver()";

    [Fact]
    public async Task Script_CallingAnUnknownFunction_RefusedWithItsLine_NothingRuns()
    {
        // A controller compiles a program before it runs it: a call of something that does not exist refuses the whole program.
        await using var controller = new VirtualUrController(new VirtualUrControllerOptions { InstantExecution = true });
        await controller.StartAsync();
        using var script = new TcpClient();
        await script.ConnectAsync(IPAddress.Loopback, controller.Port);
        await script.GetStream().WriteAsync(Encoding.ASCII.GetBytes("def hello():\n  textmsg(\"hi\")\n  no_such_thing(1)\nend\n"));
        await WaitUntilAsync(() => controller.Errors.Count == 1);

        Assert.Equal("Compile error: line 3: unknown function 'no_such_thing'", controller.Errors[0]);
        Assert.DoesNotContain("hi", controller.PendantMessages);
        Assert.False(controller.IsProgramRunning);
        Assert.Equal(1, controller.ScriptsReceived);
    }

    [Fact]
    public async Task OurDriver_CallLineAfterItsEnd_IsTheSameScriptAndTheProgramRunsOn()
    {
        // The original Machina.NET host follows the definition with a call line; a slow link can deliver it apart. The program
        // starts at its "end" (script manual), and the call line that follows must not replace it.
        await using var controller = new VirtualUrController(new VirtualUrControllerOptions { InstantExecution = true });
        await controller.StartAsync();
        var server = new TcpListener(IPAddress.Loopback, 0);
        server.Start();
        using var scriptClient = new TcpClient();
        await scriptClient.ConnectAsync(IPAddress.Loopback, controller.Port);
        string definition = UrDriverScript.For("127.0.0.1", ((IPEndPoint)server.LocalEndpoint).Port);
        string call = "\n\n# Kickstart the driver\nmachina_ur_driver()\n";

        await scriptClient.GetStream().WriteAsync(Encoding.ASCII.GetBytes(definition));
        using var driver = await server.AcceptTcpClientAsync().WaitAsync(Timeout);
        var stream = driver.GetStream();
        Assert.Equal(new int[] { -50, 3, 0, 0, int.MinValue }, await WireInts.ReadAsync(stream, 5, Timeout));
        await WireInts.ReadAsync(stream, 14, Timeout);
        await scriptClient.GetStream().WriteAsync(Encoding.ASCII.GetBytes(call));
        // The call line belongs to the program that just started: it is neither a new program nor kept as one.
        await WaitUntilAsync(() => controller.PendantMessages.Contains("Machina driver 3.0.0 connected to 127.0.0.1"));

        Assert.Equal(1, controller.ScriptsReceived);
        Assert.True(controller.IsProgramRunning);
        Assert.Empty(controller.Errors);
        await WireInts.WriteAsync(stream, [1, 8, 20]); // id 1: blend code 8 with 20 on the wire, as in OurDriver_UnknownCode_…
        Assert.Equal(new int[] { 1 }, await WireInts.ReadAsync(stream, 1, Timeout));
        Assert.Equal(["1 8 20"], controller.ReceivedRequests); // what the driver read on its socket: id, code, the blend
        Assert.Equal(1, controller.ScriptsReceived);
        server.Stop();
    }

    [Theory]
    [InlineData(true)]
    [InlineData(false)]
    public async Task Script_WithoutAFinalLineBreak_Starts(bool originalHost)
    {
        // Script manual: a program is complete at its "end" in column 1. The original host sends its call line after it with no
        // line break at all; our driver's upload ends with "end". Either way the program starts with the connection left open.
        await using var controller = new VirtualUrController(new VirtualUrControllerOptions { InstantExecution = true });
        await controller.StartAsync();
        using var link = await HostAsync(controller, port => originalHost
            ? UploadedTheOriginalWay(port)
            : UrDriverScript.For("127.0.0.1", port, instance: 77).TrimEnd('\n'));
        var stream = link.Driver.GetStream();
        int[] greeting = await WireInts.ReadAsync(stream, 19, Timeout);

        Assert.Equal(new[] { -50, 3, 0, 0, int.MinValue, -54 }, greeting[..6]);
        Assert.True(controller.IsProgramRunning);
        Assert.Equal(2u, controller.RuntimeState);
        Assert.Equal(77, controller.InstanceRegister);
        Assert.Equal(1, controller.ScriptsReceived);
        Assert.Empty(controller.Errors);
    }

    [Fact]
    public async Task OurDriver_UnknownCode_RecordedAndProgramStops()
    {
        await using var controller = new VirtualUrController(new VirtualUrControllerOptions { InstantExecution = true });
        await controller.StartAsync();
        using var link = await HostAsync(controller, port => UrDriverScript.For("127.0.0.1", port));
        var stream = link.Driver.GetStream();
        Assert.Equal(new int[] { -50, 3, 0, 0, int.MinValue }, await WireInts.ReadAsync(stream, 5, Timeout));
        await WireInts.ReadAsync(stream, 14, Timeout);
        await WireInts.WriteAsync(stream, [1, 8, 20, 2, 99]);
        Assert.Equal(new int[] { 1 }, await WireInts.ReadAsync(stream, 1, Timeout));
        await WaitUntilAsync(() => !controller.IsProgramRunning);
        // The driver itself says so on the pendant and halts: a halt is the program's end, not an error of the controller.
        Assert.Contains("Machina: unknown instruction code, stopping: 99", controller.PendantMessages);
        Assert.Empty(controller.Errors);
        Assert.Equal(["1 8 20"], controller.ReceivedRequests); // instruction 2 was read but never acknowledged
    }

    /// <summary>Plays the host: opens a server, sends the script made for its port, and takes the connection the driver opens back.</summary>
    private static async Task<HostLink> HostAsync(VirtualUrController controller, Func<int, string> script)
    {
        var server = new TcpListener(IPAddress.Loopback, 0);
        server.Start();
        var scriptClient = new TcpClient();
        await scriptClient.ConnectAsync(IPAddress.Loopback, controller.Port);
        await scriptClient.GetStream().WriteAsync(Encoding.ASCII.GetBytes(script(((IPEndPoint)server.LocalEndpoint).Port)));
        var driver = await server.AcceptTcpClientAsync().WaitAsync(Timeout);
        return new HostLink(server, scriptClient, driver);
    }

    private sealed record HostLink(TcpListener Server, TcpClient Script, TcpClient Driver) : IDisposable
    {
        public void Dispose()
        {
            Driver.Dispose();
            Script.Dispose();
            Server.Stop();
        }
    }

    private static async Task WaitUntilAsync(Func<bool> condition)
    {
        long start = TimeProvider.System.GetTimestamp();
        while (!condition())
        {
            Assert.True(TimeProvider.System.GetElapsedTime(start) < Timeout, "timed out");
            await Task.Delay(5);
        }
    }
}
