using System.Net;
using System.Net.Sockets;
using Machina.Simulation.UrScript;
using Machina.Tests.Support;

namespace Machina.Tests.Simulation.UrScript;

/// <summary>
/// A secondary program's socket read is bounded by its one controller step (the Script Manual's "Secondary Program
/// Limitations": socket use there is "limited to executing simple non-blocking commands"; a "slow remote server ... will cause
/// 'Runtime too much behind'"). The twin used to let it wait its whole timeout (2 s by default, for ever with 0) beside the main
/// program, as a main program's read waits.
/// </summary>
public sealed class UrSecondarySocketTests
{
    private static readonly TimeSpan Bound = TimeSpan.FromMinutes(1);

    /// <summary>A server that accepts and never sends: the secondary program's read stops it with the error and a protective stop.</summary>
    [Fact]
    public void ASecProgram_ReadingASocketThatHasNothing_StopsTooMuchBehind_WithAProtectiveStop()
    {
        using var server = new TcpListener(IPAddress.Loopback, 0);
        server.Start();
        int port = ((IPEndPoint)server.LocalEndpoint).Port;
        var clock = new ManualClock();
        using var twin = new UrTwinController(new UrTwinOptions { Time = clock, RealTime = true });
        Assert.True(twin.Start("def main():\n  textmsg(\"main started\")\n  while True:\n    sleep(1)\n  end\nend\n"), twin.Error);
        Assert.True(SpinWait.SpinUntil(() => twin.Pendant.Lines.Contains("main started"), Bound), "the main program did not start");

        twin.Receive($"sec reading():\n  socket_open(\"127.0.0.1\", {port}, \"peer\")\n  write_output_integer_register(3, 1)\n  x = socket_read_binary_integer(1, \"peer\")\n  write_output_integer_register(3, 2)\nend\n");
        using Socket peer = server.AcceptSocket(); // held open, nothing sent
        Assert.True(SpinWait.SpinUntil(() => twin.SecondaryProgramsRun == 1, Bound), $"the secondary program did not end: {twin.Error}");

        string error = Assert.Single(twin.SecondaryErrors);
        Assert.StartsWith("Secondary program: Runtime error: line 4: Runtime is too much behind (socket_read_binary_integer", error);
        Assert.Equal(1, twin.Io.GetNumber(UrIoBanks.OutputIntRegisters, 3)); // it went no further than the read
        Assert.Contains("Protective stop: Runtime is too much behind", twin.Pendant.Lines);
        Assert.True(twin.IsHeld);
        Assert.Equal(UrProgramState.Running, twin.State);
    }
}
