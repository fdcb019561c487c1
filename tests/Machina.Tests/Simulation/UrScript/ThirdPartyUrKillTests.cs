using System.Net;
using System.Net.Sockets;
using Machina.Simulation.UrScript;

namespace Machina.Tests.Simulation.UrScript;

/// <summary>
/// What UR's client library's external control script needs of <c>kill</c> as it ends (session 30's re-run of the third-party
/// clients, docs/reliability.md): it kills its script-command thread, which reads a socket with timeout 0, then closes that
/// socket. The Script Manual's <c>kill</c> terminates the thread: a killed thread never runs another statement. On the twin the
/// killed thread went on reading when its peer had closed the connection first (a read of a closed connection does not wait),
/// so it read the socket after the close and stopped the ended program with <c>socket … is not open</c> (9 of 10 runs through
/// <c>machina sim ur</c>; in program time, without real time, the reader did not run between the kill and the end). Written here as our own program.
/// </summary>
public sealed class ThirdPartyUrKillTests
{
    [Fact]
    public async Task KilledThread_ReadingAClosedConnection_RunsNoStatementAfterTheKill()
    {
        using var listener = new TcpListener(IPAddress.Loopback, 0);
        listener.Start();
        int port = ((IPEndPoint)listener.LocalEndpoint).Port;
        using var bounded = new CancellationTokenSource(TimeSpan.FromSeconds(30));
        Task peer = Task.Run(async () =>
        {
            // The host's end closes first, as the client library's did before the script ended.
            using TcpClient client = await listener.AcceptTcpClientAsync(bounded.Token);
            client.Close();
        }, bounded.Token);

        // In real time, as machina sim ur runs it: the main program's waits are on the wall clock, and the reader spins meanwhile.
        using var twin = new UrTwinController(new UrTwinOptions { RealTime = true });
        UrProgramState state = twin.Run($$"""
            def prog():
              socket_open("127.0.0.1", {{port}}, "cmd")
              global reads = 0
              thread reader():
                while True:
                  r = socket_read_binary_integer(1, "cmd", 0)
                  reads = reads + 1
                end
              end
              t = run reader()
              while reads < 3:
                sync()
              end
              kill t
              socket_close("cmd")
              sleep(0.2)
              textmsg("ended")
            end
            """, bounded.Token);
        await peer;

        Assert.True(state == UrProgramState.Finished, twin.Error);
        Assert.Null(twin.Error);
        Assert.Contains("ended", twin.Pendant.Lines);
    }

    /// <summary>
    /// The same rule without a socket: a thread that only counts gives the others the machine only where its loop yields, so
    /// <c>kill</c> always finds it there; it must not count once more after it.
    /// </summary>
    [Fact]
    public void KilledThread_CountingInALoop_CountsNoMoreAfterTheKill()
    {
        using var bounded = new CancellationTokenSource(TimeSpan.FromSeconds(30));
        using var twin = new UrTwinController(new UrTwinOptions { RealTime = true });
        UrProgramState state = twin.Run("""
            def prog():
              global count = 0
              thread counter():
                while True:
                  count = count + 1
                end
              end
              t = run counter()
              while count < 3:
                sync()
              end
              kill t
              before = count
              sleep(0.1)
              textmsg("after the kill: ", count - before)
            end
            """, bounded.Token);

        Assert.True(state == UrProgramState.Finished, twin.Error);
        Assert.Contains("after the kill: 0", twin.Pendant.Lines);
    }
}
