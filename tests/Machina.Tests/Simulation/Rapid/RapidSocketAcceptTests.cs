using System.Globalization;
using System.Net;
using System.Net.Sockets;
using System.Text;
using Machina.Simulation.Rapid;

namespace Machina.Tests.Simulation.Rapid;

/// <summary>
/// SocketAccept on the RAPID twin when its wait ends without a client (issue 40): the accept it started is withdrawn. Before,
/// it stayed pending and took the next client, which no program greeted or read: a host that reconnected to a virtual ABB
/// restarting under it waited its whole connect timeout (2 of 200 restart trials), and a program that retries SocketAccept
/// after ERR_SOCK_TIMEOUT never saw the client that came.
/// </summary>
public class RapidSocketAcceptTests
{
    private static readonly TimeSpan Wait = TimeSpan.FromSeconds(10);

    [Fact]
    public async Task SocketAccept_TimedOutAndRetried_TheClientThatComesIsServed()
    {
        var listener = new TcpListener(IPAddress.Loopback, 0);
        listener.Start();
        int port = ((IPEndPoint)listener.LocalEndpoint).Port;
        var twin = new RapidTwinController();
        twin.Reserve(listener);
        twin.Load(("T.mod", $$"""
            MODULE T
            VAR socketdev server;
            VAR socketdev client;
            VAR string text;
            PROC main()
              SocketCreate server;
              SocketBind server, "127.0.0.1", {{port.ToString(CultureInfo.InvariantCulture)}};
              SocketListen server;
              SocketAccept server, client \Time:=1;
              SocketSend client \Str:="hello";
              SocketReceive client \Str:=text \Time:=10;
              TPWrite text;
              SocketClose client;
              SocketClose server;
            ERROR
              IF ERRNO = ERR_SOCK_TIMEOUT THEN
                TPWrite "no client yet";
                RETRY;
              ENDIF
            ENDPROC
            ENDMODULE
            """));
        using var stop = new CancellationTokenSource(TimeSpan.FromSeconds(60));
        Task<RapidProgramState> run = Task.Run(() => twin.Run("main", stop.Token));
        try
        {
            // After the first SocketAccept gave up: its accept must not be the one that takes the client.
            Assert.True(SpinWait.SpinUntil(() => twin.Pendant.Lines.Contains("no client yet") || run.IsCompleted, Wait), "the first SocketAccept to time out");
            using var client = new TcpClient { NoDelay = true };
            using (var connect = new CancellationTokenSource(Wait))
            {
                await client.ConnectAsync(IPAddress.Loopback, port, connect.Token);
            }
            var buffer = new byte[5];
            int read = 0;
            using (var greeting = new CancellationTokenSource(Wait))
            {
                while (read < buffer.Length)
                {
                    int n = await client.GetStream().ReadAsync(buffer.AsMemory(read), greeting.Token);
                    Assert.NotEqual(0, n);
                    read += n;
                }
            }
            Assert.Equal("hello", Encoding.ASCII.GetString(buffer));
            await client.GetStream().WriteAsync(Encoding.ASCII.GetBytes("bye"));

            Assert.Equal(RapidProgramState.Finished, await run.WaitAsync(Wait));
            Assert.Equal("bye", twin.Pendant.Lines[^1]);
        }
        finally
        {
            await stop.CancelAsync();
            await Task.WhenAny(run, Task.Delay(Wait));
            listener.Stop();
        }
    }
}
