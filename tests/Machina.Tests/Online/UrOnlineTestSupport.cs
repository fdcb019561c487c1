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

    internal static Task<Robot> ConnectUrAsync(VirtualUrController controller, Action<Robot>? configure = null, string name = "HelloRobot") =>
        OnlineTestSupport.ConnectRobotAsync(name, "UR", controller.Port, configure);
}
