using Machina.Simulation;
using Machina.Tests.Support;

namespace Machina.Tests.Online;

/// <summary>Starts virtual ABB controllers on loopback and connects robots to them, with bounded waits only.</summary>
internal static class OnlineTestSupport
{
    internal static readonly TimeSpan Limit = TimeSpan.FromSeconds(15);

    internal static async Task<VirtualAbbController> StartControllerAsync(VirtualAbbControllerOptions? options = null)
    {
        var controller = new VirtualAbbController(options ?? new VirtualAbbControllerOptions { InstantExecution = true });
        await controller.StartAsync();
        return controller;
    }

    internal static Task<Robot> ConnectAsync(VirtualAbbController controller, Action<Robot>? configure = null) =>
        ConnectRobotAsync("HelloRobot", "ABB", controller.Port, configure);

    /// <summary>
    /// An online robot of <paramref name="brand"/> connected to the virtual controller on loopback <paramref name="port"/>, set up
    /// by <paramref name="configure"/> before connecting.
    /// </summary>
    internal static async Task<Robot> ConnectRobotAsync(string name, string brand, int port, Action<Robot>? configure)
    {
        var bot = Robot.Create(name, brand);
        bot.ControlMode("online");
        bot.ConnectTimeout = Limit; // a loaded test machine may be slow to accept; no test is about this timeout
        configure?.Invoke(bot);
        await bot.ConnectAsync("127.0.0.1", port).WaitAsync(Limit);
        return bot;
    }

    /// <summary>Waits for a condition that another thread makes true, checking every few milliseconds, at most <see cref="Limit"/>.</summary>
    internal static Task EventuallyAsync(Func<bool> condition, string what) => Eventually.TrueAsync(condition, what, Limit);
}

/// <summary>A loopback server that accepts one client and never says anything (a controller without the driver).</summary>
internal sealed class SilentServer : IAsyncDisposable
{
    private readonly System.Net.Sockets.TcpListener _listener;

    private SilentServer(System.Net.Sockets.TcpListener listener)
    {
        _listener = listener;
        Port = ((System.Net.IPEndPoint)listener.LocalEndpoint).Port;
        Accepted = listener.AcceptTcpClientAsync();
    }

    internal int Port { get; }

    /// <summary>Completes when the client connected.</summary>
    internal Task<System.Net.Sockets.TcpClient> Accepted { get; }

    internal static SilentServer Start()
    {
        var listener = new System.Net.Sockets.TcpListener(System.Net.IPAddress.Loopback, 0);
        listener.Start();
        return new SilentServer(listener);
    }

    public async ValueTask DisposeAsync()
    {
        _listener.Stop();
        try
        {
            (await Accepted).Dispose();
        }
        catch (Exception ex) when (ex is System.Net.Sockets.SocketException or ObjectDisposedException or OperationCanceledException)
        {
            // Nobody connected.
        }
    }
}
