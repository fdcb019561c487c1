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
        Assert.Equal(new int[] { -50, 2, 0, 0, int.MinValue }, await WireInts.ReadAsync(stream, 5, Timeout));
        await WireInts.ReadAsync(stream, 14, Timeout);
        await scriptClient.GetStream().WriteAsync(Encoding.ASCII.GetBytes(call));
        // The call line belongs to the program that just started: it is neither a new program nor kept as one.
        await WaitUntilAsync(() => controller.PendantMessages.Contains("Machina driver 2.0.0 connected to 127.0.0.1"));

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

        Assert.Equal(new[] { -50, 2, 0, 0, int.MinValue, -54 }, greeting[..6]);
        Assert.True(controller.IsProgramRunning);
        Assert.Equal(2u, controller.RuntimeState);
        Assert.Equal(77, controller.InstanceRegister);
        Assert.Equal(1, controller.ScriptsReceived);
        Assert.Empty(controller.Errors);
    }

    [Theory]
    [InlineData("def p():\n  x = 1\nend", false, "def p():\n  x = 1\nend")]
    [InlineData("def p():\n  x = 1\nend\nmore", false, "def p():\n  x = 1\nend\n")]
    [InlineData("# c\n\ndef p():\n  x = 1\nen", false, null)]
    [InlineData("def p():\n  x = 1\n  end\n", false, null)]
    [InlineData("textmsg(1)", false, null)]
    [InlineData("textmsg(1)", true, "textmsg(1)")]
    [InlineData("textmsg(1)\ndef p():\n", false, "textmsg(1)\n")]
    [InlineData("sec s():\n  x = 1\nend\r\n", false, "sec s():\n  x = 1\nend\r\n")]
    public void TakeScript_ProgramCompleteAtItsEnd_OneLinerAtItsLineBreak(string text, bool closed, string? expected)
    {
        Assert.Equal(expected, VirtualUrController.TakeScript(text, closed)?.Script);
    }

    [Theory]
    [InlineData("def prog():\n  textmsg(1)\nend\n", "prog")]
    [InlineData("# header\ndef machina_ur_driver():\n  x = 1\nend\n\n\n", "machina_ur_driver")]
    [InlineData("def prog():\n  textmsg(1)\nend\nprog()\n", null)]
    [InlineData("textmsg(1)\n", null)]
    public void DefinedWithoutCall_ScriptEndingWithADefinition_NamesIt(string script, string? expected)
    {
        Assert.Equal(expected, VirtualUrController.DefinedWithoutCall(script));
    }

    [Theory]
    [InlineData("machina_ur_driver()\n", true)]
    [InlineData("\n\n# Kickstart the driver\nmachina_ur_driver()\n", true)]
    [InlineData("machina_ur_driver( )\n", true)]
    [InlineData("other()\n", false)]
    [InlineData("machina_ur_driver()\nhalt\n", false)]
    [InlineData("  textmsg(1)\nmachina_ur_driver()\n", false)]
    public void IsOnlyCallOf_ScriptOfJustTheCall_IsRecognised(string script, bool expected)
    {
        Assert.Equal(expected, VirtualUrController.IsOnlyCallOf(script, "machina_ur_driver"));
    }

    [Theory]
    [InlineData("  MACHINA_DRIVER_VERSION = [2, 0, 0]\n", "Ours")]
    [InlineData("  MACHINA_DRIVER_VERSION = \"1.2.0\"\n", "Original")]
    [InlineData("  MACHINA_DRIVER_VERSION = \"3.0.0\"\n", "None")]
    [InlineData("", "None")]
    public void Recognise_VersionLine_TellsTheDriver(string versionLine, string kind)
    {
        string script = "def machina_ur_driver():\n" + versionLine + "  HOSTNAME = \"10.0.0.5\"\n  PORT = 51234   # the host\nend\nmachina_ur_driver()\n";
        var (k, host, port) = VirtualUrController.Recognise(script);
        Assert.Equal(kind, k.ToString());
        if (kind != "None")
        {
            Assert.Equal(("10.0.0.5", 51234), (host, port));
        }
    }

    [Fact]
    public async Task OurDriver_UnknownCode_RecordedAndProgramStops()
    {
        await using var controller = new VirtualUrController(new VirtualUrControllerOptions { InstantExecution = true });
        await controller.StartAsync();
        using var link = await HostAsync(controller, port => UrDriverScript.For("127.0.0.1", port));
        var stream = link.Driver.GetStream();
        Assert.Equal(new int[] { -50, 2, 0, 0, int.MinValue }, await WireInts.ReadAsync(stream, 5, Timeout));
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
