using System.Diagnostics;
using System.Net;
using System.Net.Sockets;
using System.Text;

namespace Machina.Tests.Rws;

/// <summary>
/// The RWS client against answers no controller sends (issue 40): a huge answer is refused before it fills the memory, a deeply
/// nested one is refused before it is walked, and a controller's text with escape codes is shown printable.
/// </summary>
public sealed class RwsClientLimitsTests
{
    [Fact]
    public async Task Answer_DeclaringOnePointFiveGiB_RefusedAtOnce_WithTheReason()
    {
        await using var server = CannedServer.Start("HTTP/1.1 200 OK\r\nContent-Type: application/xhtml+xml\r\nContent-Length: 1610612736\r\n\r\n", stream: 0);
        using var client = Client(server.Port);

        var ex = await Assert.ThrowsAsync<RobotWebServicesException>(() => client.GetOperationModeAsync());

        Assert.Equal("Could not read the operating mode: the controller's answer (HTTP 200) declares 1610612736 bytes; Machina reads at most " +
            "16777216 bytes of an answer (Robot Web Services answers are a few kilobytes). Check the address: it may not be a controller.", ex.Message);
    }

    [Fact]
    public async Task Answer_WithoutLength_GoingPastTheCap_Refused_OnlyTheCapRead()
    {
        // 4 MiB sent, 1 MiB taken: the client stops reading at the cap.
        await using var server = CannedServer.Start("HTTP/1.1 200 OK\r\nContent-Type: application/xhtml+xml\r\nConnection: close\r\n\r\n", stream: 4 << 20);
        using var client = Client(server.Port, maxAnswer: 1 << 20);

        var ex = await Assert.ThrowsAsync<RobotWebServicesException>(() => client.GetOperationModeAsync());

        Assert.StartsWith("Could not read the operating mode: the controller's answer (HTTP 200) goes on past that; Machina reads at most 1048576 bytes", ex.Message, StringComparison.Ordinal);
    }

    [Fact]
    public async Task ErrorText_WithEscapeCodes_IsShownPrintable()
    {
        const string body = "\u001b[2J\u001b]0;owned\u0007gone\r\n";
        await using var server = CannedServer.Start($"HTTP/1.1 500 Internal Server Error\r\nContent-Type: text/plain\r\nContent-Length: {body.Length}\r\n\r\n{body}", stream: 0);
        using var client = Client(server.Port);

        var ex = await Assert.ThrowsAsync<RobotWebServicesException>(() => client.GetOperationModeAsync());

        Assert.Equal("Could not read the operating mode: the controller answered HTTP 500: \\x1b[2J\\x1b]0;owned\\x07gone\\r\\n", ex.Message);
    }

    [Fact]
    public void DeeplyNestedAnswer_RefusedBeforeItIsWalked_InLinearTime()
    {
        // 50,000 nested spans (1.5 MB): walking each span's text was quadratic (seconds to minutes); refused at depth 33 now.
        const int depth = 50_000;
        var text = new StringBuilder("<html xmlns=\"http://www.w3.org/1999/xhtml\"><body>");
        text.Insert(text.Length, "<span class=\"opmode\">", depth).Append("AUTO").Insert(text.Length, "</span>", depth).Append("</body></html>");
        var clock = Stopwatch.StartNew();

        var ex = Assert.Throws<RobotWebServicesException>(() => RwsXhtml.Value(text.ToString(), "opmode"));

        Assert.StartsWith("The controller's answer nests elements more than 32 deep; it is not the XHTML of Robot Web Services:", ex.Message, StringComparison.Ordinal);
        Assert.True(clock.Elapsed < TimeSpan.FromSeconds(2), $"refusing took {clock.Elapsed.TotalMilliseconds} ms");
        // An answer as deep as a controller's is read.
        Assert.Equal("AUTO", RwsXhtml.Value("<html><body><div><ul><li><span class=\"opmode\">AUTO</span></li></ul></div></body></html>", "opmode"));
    }

    private static RwsClient Client(int port, long maxAnswer = 16 << 20) =>
        new("127.0.0.1", new RobotWebServicesOptions { Port = port, Timeout = TimeSpan.FromSeconds(15), MaxAnswerBytes = maxAnswer });

    /// <summary>A one-answer HTTP server: reads a request head, writes <c>head</c>, then <c>stream</c> bytes of filler (or until the client leaves).</summary>
    private sealed class CannedServer : IAsyncDisposable
    {
        private readonly TcpListener _listener = new(IPAddress.Loopback, 0);
        private readonly CancellationTokenSource _stop = new();
        private Task _serving = Task.CompletedTask;

        public int Port => ((IPEndPoint)_listener.LocalEndpoint).Port;

        public static CannedServer Start(string head, int stream)
        {
            var server = new CannedServer();
            server._listener.Start();
            server._serving = server.ServeAsync(Encoding.Latin1.GetBytes(head), stream, server._stop.Token);
            return server;
        }

        private async Task ServeAsync(byte[] head, int stream, CancellationToken token)
        {
            try
            {
                using TcpClient client = await _listener.AcceptTcpClientAsync(token);
                NetworkStream network = client.GetStream();
                var seen = new List<byte>();
                var one = new byte[1];
                while (!(seen.Count >= 4 && seen[^4] == '\r' && seen[^3] == '\n' && seen[^2] == '\r' && seen[^1] == '\n'))
                {
                    if (await network.ReadAsync(one, token) == 0)
                    {
                        return;
                    }
                    seen.Add(one[0]);
                }
                await network.WriteAsync(head, token);
                byte[] filler = Encoding.ASCII.GetBytes(new string('x', 64 * 1024));
                for (int sent = 0; sent < stream; sent += filler.Length)
                {
                    await network.WriteAsync(filler, token);
                }
                // Held open (a declared length never sent) until the client leaves or the test ends.
                while (await network.ReadAsync(one, token) > 0)
                {
                }
            }
            catch (Exception e) when (e is IOException or SocketException or OperationCanceledException or ObjectDisposedException)
            {
                // The client left, or the test ended.
            }
        }

        public async ValueTask DisposeAsync()
        {
            await _stop.CancelAsync();
            _listener.Stop();
            await _serving;
            _stop.Dispose();
        }
    }
}
