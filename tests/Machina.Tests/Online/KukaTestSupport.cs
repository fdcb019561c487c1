using System.Collections.Concurrent;
using System.Globalization;
using System.Net;
using System.Net.Sockets;
using Machina.Simulation;

namespace Machina.Tests.Online;

/// <summary>Starts virtual KUKA controllers on loopback and connects KUKA robots to them, with bounded waits only.</summary>
internal static class KukaTestSupport
{
    internal static async Task<VirtualKukaController> StartKukaAsync(VirtualKukaControllerOptions? options = null)
    {
        var controller = new VirtualKukaController(options ?? new VirtualKukaControllerOptions { InstantExecution = true });
        await controller.StartAsync();
        return controller;
    }

    /// <summary>A KUKA robot connected to <paramref name="controller"/>, recording the ids it sees executed and its lost connections.</summary>
    internal static async Task<(Robot Bot, ConcurrentQueue<int> Executed, TaskCompletionSource<ConnectionLostArgs> Lost)> ConnectKukaAsync(
        VirtualKukaController controller, Action<Robot>? configure = null)
    {
        var executed = new ConcurrentQueue<int>();
        var lost = new TaskCompletionSource<ConnectionLostArgs>(TaskCreationOptions.RunContinuationsAsynchronously);
        Robot bot = await OnlineTestSupport.ConnectRobotAsync("KukaBot", "KUKA", controller.Port, b =>
        {
            b.ActionExecuted += (_, e) => executed.Enqueue(e.LastAction.Id);
            b.ConnectionLost += (_, e) => lost.TrySetResult(e);
            configure?.Invoke(b);
        });
        return (bot, executed, lost);
    }

    /// <summary>The ids of the actions the controller received, from its log of A elements, in order.</summary>
    internal static List<int> ReceivedIds(VirtualKukaController controller) =>
        [.. controller.ReceivedRequests.Select(r => int.Parse(r[(r.IndexOf("ID=\"", StringComparison.Ordinal) + 4)..r.IndexOf("\" T=", StringComparison.Ordinal)], CultureInfo.InvariantCulture))];

    /// <summary>How long the raw wire helpers below wait for a connection or an element.</summary>
    private static readonly TimeSpan RawWait = TimeSpan.FromSeconds(10);

    /// <summary>A raw TCP client connected to a KUKA controller's port, for tests that speak the wire themselves (bounded wait).</summary>
    internal static async Task<TcpClient> ConnectRawAsync(int port)
    {
        var client = new TcpClient { NoDelay = true };
        using var cts = new CancellationTokenSource(RawWait);
        await client.ConnectAsync(IPAddress.Loopback, port, cts.Token);
        return client;
    }

    /// <summary>Reads the next whole XML element from <paramref name="client"/> (bounded wait; a closed connection fails the test).</summary>
    internal static async Task<KukaElement> ReadElementAsync(TcpClient client, KukaXmlReader reader)
    {
        using var cts = new CancellationTokenSource(RawWait);
        var bytes = new byte[4096];
        KukaElement element;
        while (!reader.TryRead(out element))
        {
            int n = await client.GetStream().ReadAsync(bytes, cts.Token);
            Assert.NotEqual(0, n);
            reader.Append(bytes.AsSpan(0, n));
        }
        return element;
    }
}
