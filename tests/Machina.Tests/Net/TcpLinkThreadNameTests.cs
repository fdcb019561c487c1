using System.Net;
using System.Net.Sockets;

namespace Machina.Tests.Net;

/// <summary>
/// The thread that reads a link is named after its role: a driver's main link "Machina link", a side link (a monitor, UR's RTDE
/// or script port) "Machina side", so that a per-thread reading (the benchmarks', a debugger's) tells the two apart.
/// </summary>
public sealed class TcpLinkThreadNameTests
{
    private static readonly TimeSpan Bound = TimeSpan.FromSeconds(20);

    [Fact]
    public async Task Start_WithoutAName_ReadsOnTheMachinaLinkThread()
    {
        Assert.Equal("Machina link", await ReaderThreadNameAsync(null));
    }

    [Fact]
    public async Task Start_AsASideLink_ReadsOnTheMachinaSideThread()
    {
        Assert.Equal("Machina side", await ReaderThreadNameAsync(TcpLink.SideThreadName));
    }

    /// <summary>The name of the thread that handles a byte sent to a link started with <paramref name="name"/> (the default when null).</summary>
    private static async Task<string?> ReaderThreadNameAsync(string? name)
    {
        var listener = new TcpListener(IPAddress.Loopback, 0);
        listener.Start();
        try
        {
            int port = ((IPEndPoint)listener.LocalEndpoint).Port;
            Task<Socket> accepting = listener.AcceptSocketAsync();
            await using TcpLink link = await TcpLink.ConnectAsync("127.0.0.1", port, Bound, TimeProvider.System, CancellationToken.None);
            using Socket server = await accepting.WaitAsync(Bound);
            var receiver = new NamingReceiver();
            if (name is null)
            {
                link.Start(receiver);
            }
            else
            {
                link.Start(receiver, name);
            }
            await server.SendAsync(new byte[] { 1 });
            return await receiver.ThreadName.Task.WaitAsync(Bound);
        }
        finally
        {
            listener.Stop();
        }
    }

    private sealed class NamingReceiver : ILinkReceiver
    {
        public TaskCompletionSource<string?> ThreadName { get; } = new(TaskCreationOptions.RunContinuationsAsynchronously);

        public void OnReceived(ReadOnlySpan<byte> data) => ThreadName.TrySetResult(Thread.CurrentThread.Name);

        public void OnClosed(Exception? error) => ThreadName.TrySetResult("closed");
    }
}
