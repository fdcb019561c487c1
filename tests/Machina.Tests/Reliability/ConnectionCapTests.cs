using System.Net;
using System.Net.Sockets;
using System.Text;
using Machina.Simulation;
using Machina.Simulation.Rapid;
using Machina.Simulation.Rws;
using Machina.Simulation.Twin;
using Machina.Tests.Support;

namespace Machina.Tests.Reliability;

/// <summary>
/// Connections per port (issue 40): a twin's port serves a bounded number of clients at once; one past the limit is closed at
/// once with a line that says why (the RWS twin answers it 503), and a place freed by a client that left is taken again.
/// Before, every connection was served (a task and its buffers each, without end).
/// </summary>
public class ConnectionCapTests
{
    private static readonly TimeSpan Wait = TimeSpan.FromSeconds(10);

    [Fact]
    public void Cap_CountsUpToItsLimit_AndALeaveFreesAPlace()
    {
        var cap = new ConnectionCap(2);
        Assert.True(cap.TryEnter());
        Assert.True(cap.TryEnter());
        Assert.False(cap.TryEnter());
        Assert.Equal(2, cap.Open);
        cap.Leave();
        Assert.True(cap.TryEnter());
        Assert.Equal("port 29999: connection from 127.0.0.1:5000 refused: 2 connections are open, the most this port serves at once",
            cap.Refusal("port 29999", "127.0.0.1:5000"));
        Assert.Throws<ArgumentOutOfRangeException>(() => new ConnectionCap(0));
    }

    [Fact]
    public async Task UrDashboard_OnePastTheLimit_ClosedAtOnceAndLogged_APlaceFreedIsTakenAgain()
    {
        await using var controller = new VirtualUrController(new VirtualUrControllerOptions { InstantExecution = true });
        await controller.StartAsync();
        var clients = new List<TcpClient>();
        try
        {
            for (int i = 0; i < VirtualUrController.MaxClientsPerPort; i++)
            {
                TcpClient client = await ConnectAsync(controller.DashboardPort);
                clients.Add(client);
                Assert.Equal("Connected: Universal Robots Dashboard Server", await ReadLineAsync(client));
            }

            using (TcpClient extra = await ConnectAsync(controller.DashboardPort))
            {
                Assert.Null(await ReadLineAsync(extra)); // closed without a greeting
            }
            string refusal = $"port {controller.DashboardPort}: connection from 127.0.0.1:";
            Assert.Contains(controller.PendantMessages, m => m.StartsWith(refusal, StringComparison.Ordinal)
                && m.EndsWith($" refused: {VirtualUrController.MaxClientsPerPort} connections are open, the most this port serves at once", StringComparison.Ordinal));

            // The others are still served.
            await clients[0].GetStream().WriteAsync(Encoding.ASCII.GetBytes("robotmode\n"));
            Assert.StartsWith("Robotmode: ", await ReadLineAsync(clients[0]), StringComparison.Ordinal);

            // One leaves: a new client is served once the controller saw it go (bounded retries).
            clients[^1].Dispose();
            clients.RemoveAt(clients.Count - 1);
            string? greeting = null;
            for (int attempt = 0; attempt < 100 && greeting is null; attempt++)
            {
                TcpClient next = await ConnectAsync(controller.DashboardPort);
                greeting = await ReadLineAsync(next);
                if (greeting is null)
                {
                    next.Dispose();
                    await Task.Delay(50);
                }
                else
                {
                    clients.Add(next);
                }
            }
            Assert.Equal("Connected: Universal Robots Dashboard Server", greeting);
        }
        finally
        {
            clients.ForEach(c => c.Dispose());
        }
    }

    [Fact]
    public async Task Rws_OnePastTheLimit_Answered503AndClosed()
    {
        var twin = new RapidTwinController(new RapidTwinOptions());
        twin.Task();
        var clients = new List<TcpClient>();
        await using (var rws = new RwsTwinServer(twin))
        {
            rws.Start();
            try
            {
                for (int i = 0; i < RwsTwinServer.MaxConnections; i++)
                {
                    clients.Add(await ConnectAsync(rws.Port));
                }
                // Each of those is served: one answers a request (401: no credentials).
                await clients[0].GetStream().WriteAsync(Encoding.ASCII.GetBytes("GET /rw/panel/opmode HTTP/1.1\r\nHost: localhost\r\n\r\n"));
                Assert.Equal("HTTP/1.1 401 Unauthorized", await ReadLineAsync(clients[0]));

                using TcpClient extra = await ConnectAsync(rws.Port);
                string answer = await ReadToEndAsync(extra);
                Assert.StartsWith("HTTP/1.1 503 Service Unavailable\r\n", answer, StringComparison.Ordinal);
                Assert.Contains("Connection: close\r\n", answer, StringComparison.Ordinal);
                Assert.Contains($"{RwsTwinServer.MaxConnections} connections are open, the most this server serves at once", answer, StringComparison.Ordinal);
                Assert.Equal(1, rws.ConnectionsRefused);
            }
            finally
            {
                clients.ForEach(c => c.Dispose());
            }
        }
        Assert.True(twin.StopTasks(TimeSpan.FromSeconds(10)), "the RAPID tasks to stop");
    }

    private static async Task<TcpClient> ConnectAsync(int port)
    {
        var client = new TcpClient { NoDelay = true };
        using var cts = new CancellationTokenSource(Wait);
        await client.ConnectAsync(IPAddress.Loopback, port, cts.Token);
        return client;
    }

    /// <summary>The next line (without its end), or null when the server closed the connection first (bounded wait).</summary>
    private static async Task<string?> ReadLineAsync(TcpClient client)
    {
        using var cts = new CancellationTokenSource(Wait);
        var line = new List<byte>();
        var one = new byte[1];
        try
        {
            while (true)
            {
                int n = await client.GetStream().ReadAsync(one, cts.Token);
                if (n == 0)
                {
                    return null;
                }
                if (one[0] == '\n')
                {
                    return Encoding.ASCII.GetString([.. line]).TrimEnd('\r');
                }
                line.Add(one[0]);
            }
        }
        catch (IOException)
        {
            return null; // reset by the server: closed too
        }
    }

    /// <summary>Everything until the server closes the connection (bounded wait).</summary>
    private static async Task<string> ReadToEndAsync(TcpClient client)
    {
        using var cts = new CancellationTokenSource(Wait);
        var all = new MemoryStream();
        var buffer = new byte[4096];
        int n;
        while ((n = await client.GetStream().ReadAsync(buffer, cts.Token)) > 0)
        {
            all.Write(buffer, 0, n);
        }
        return Encoding.UTF8.GetString(all.ToArray());
    }
}
