using System.Net;
using System.Net.Sockets;
using Machina.Simulation.UrScript;
using Machina.Tests.Support;

namespace Machina.Tests.Simulation.UrScript;

/// <summary>The connection a program's <c>socket_open</c> makes: blocking for the program, never watched by the runtime's socket engine.</summary>
public sealed class UrSocketTests
{
    private static readonly TimeSpan Bound = TimeSpan.FromSeconds(20);

    [Fact]
    public async Task Connect_OpensABlockingConnection_ThatTheRuntimesSocketEngineDoesNotWatch()
    {
        using var listener = new TcpListener(IPAddress.Loopback, 0);
        listener.Start();
        int port = ((IPEndPoint)listener.LocalEndpoint).Port;
        Task<Socket> accepting = listener.AcceptSocketAsync();
        using UrSocket socket = UrSocket.Connect("127.0.0.1", port, Bound, CancellationToken.None)
            ?? throw new Xunit.Sdk.XunitException("socket_open failed");
        using Socket host = await accepting.WaitAsync(Bound);

        byte[] sent = new byte[4];
        // Nothing has arrived yet, so this receive waits: the engine watches the host's socket from now on.
        Task<int> receiving = host.ReceiveAsync(sent, SocketFlags.None);
        await host.SendAsync(new byte[] { 0, 0, 0, 1, 0xFF, 0xFF, 0xFF, 0xFE });
        UrList read = socket.ReadIntegers(2, Bound.TotalSeconds, CancellationToken.None);
        Assert.True(socket.SendInt(-7));
        Assert.Equal(4, await receiving.WaitAsync(Bound));

        Assert.Equal(new object[] { 2, 1, -2 }, read.Items);
        Assert.Equal(new byte[] { 0xFF, 0xFF, 0xFF, 0xF9 }, sent);
        Assert.True(socket.Connection.Blocking);
        if (OperatingSystem.IsLinux())
        {
            // Watched, every request the host sends would wake the engine's thread and a thread-pool worker, although the
            // program reads with poll.
            Assert.False(SocketEngine.Watches(socket.Connection), "the program's socket is registered with the runtime's epoll");
            Assert.True(SocketEngine.Watches(host), "the check sees a socket that was read asynchronously");
            using var asBefore = new Socket(SocketType.Stream, ProtocolType.Tcp);
            await asBefore.ConnectAsync(IPAddress.Loopback, port);
            Assert.True(SocketEngine.Watches(asBefore), "the check sees a socket connected as socket_open and the host's links did before");
        }
    }

    [Fact]
    public void Connect_ToAPortNobodyListensOn_GivesNothing()
    {
        var listener = new TcpListener(IPAddress.Loopback, 0);
        listener.Start();
        int port = ((IPEndPoint)listener.LocalEndpoint).Port;
        listener.Stop();

        Assert.Null(UrSocket.Connect("127.0.0.1", port, Bound, CancellationToken.None));
    }
}
