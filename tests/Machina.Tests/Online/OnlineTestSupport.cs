using Machina.Simulation;

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

    internal static async Task<Robot> ConnectAsync(VirtualAbbController controller, Action<Robot>? configure = null)
    {
        var bot = Robot.Create("HelloRobot", "ABB");
        bot.ControlMode("online");
        bot.ConnectTimeout = Limit; // a loaded test machine may be slow to accept; no test is about this timeout
        configure?.Invoke(bot);
        await bot.ConnectAsync("127.0.0.1", controller.Port).WaitAsync(Limit);
        return bot;
    }

    /// <summary>Waits for a condition that another thread makes true, checking every few milliseconds, at most <see cref="Timeout"/>.</summary>
    internal static async Task EventuallyAsync(Func<bool> condition, string what)
    {
        long start = TimeProvider.System.GetTimestamp();
        while (!condition())
        {
            if (TimeProvider.System.GetElapsedTime(start) > Limit)
            {
                Assert.Fail($"Timed out waiting for {what}.");
            }
            await Task.Delay(5);
        }
    }
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
