using System.Collections.Concurrent;
using System.Globalization;
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
}
