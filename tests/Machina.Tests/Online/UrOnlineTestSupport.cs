using Machina.Simulation;

namespace Machina.Tests.Online;

/// <summary>Starts virtual UR controllers on loopback (OS-chosen ports) and connects robots to them, with bounded waits only.</summary>
internal static class UrOnlineTestSupport
{
    internal static async Task<VirtualUrController> StartUrAsync(VirtualUrControllerOptions? options = null)
    {
        var controller = new VirtualUrController(options ?? new VirtualUrControllerOptions { InstantExecution = true });
        await controller.StartAsync();
        return controller;
    }

    internal static async Task<Robot> ConnectUrAsync(VirtualUrController controller, Action<Robot>? configure = null, string name = "HelloRobot")
    {
        var bot = Robot.Create(name, "UR");
        bot.ControlMode("online");
        bot.ConnectTimeout = OnlineTestSupport.Limit;
        configure?.Invoke(bot);
        await bot.ConnectAsync("127.0.0.1", controller.Port).WaitAsync(OnlineTestSupport.Limit);
        return bot;
    }
}
