using Machina.Simulation;

namespace Machina.Bridge;

/// <summary>A virtual controller running inside the bridge, and the loopback port its driver listens on.</summary>
internal sealed record EmbeddedController(int Port, IAsyncDisposable Owner);

/// <summary>
/// The virtual controllers the bridge can start in place of a real one, by brand. Adding a brand is one line in
/// <see cref="For"/> and one small start method.
/// </summary>
internal static class EmbeddedControllers
{
    /// <summary>Starts a virtual controller for a brand, or null when Machina has none for it yet.</summary>
    internal static Func<BridgeOptions, CancellationToken, Task<EmbeddedController>>? For(RobotType brand) => brand switch
    {
        RobotType.ABB => StartAbbAsync,
        RobotType.UR => StartUrAsync,
        RobotType.KUKA => StartKukaAsync,
        _ => null,
    };

    private static Task<EmbeddedController> StartAbbAsync(BridgeOptions options, CancellationToken cancellationToken)
    {
        var controller = new VirtualAbbController(new VirtualAbbControllerOptions
        {
            // An IRB 1200-5/0.9 reaches the paper's Hello Robot, which the default IRB 120 cannot.
            Model = RobotModels.Get("IRB 1200-5/0.9"),
            SpeedFactor = options.SimulationSpeed,
            TimeProvider = options.TimeProvider,
        });
        return StartAsync(controller, () => controller.Port, cancellationToken);
    }

    private static Task<EmbeddedController> StartUrAsync(BridgeOptions options, CancellationToken cancellationToken)
    {
        var controller = new VirtualUrController(new VirtualUrControllerOptions { SpeedFactor = options.SimulationSpeed, TimeProvider = options.TimeProvider });
        return StartAsync(controller, () => controller.Port, cancellationToken);
    }

    private static Task<EmbeddedController> StartKukaAsync(BridgeOptions options, CancellationToken cancellationToken)
    {
        var controller = new VirtualKukaController(new VirtualKukaControllerOptions { SpeedFactor = options.SimulationSpeed, TimeProvider = options.TimeProvider });
        return StartAsync(controller, () => controller.Port, cancellationToken);
    }

    /// <summary>Starts a controller and hands it over with the port its driver listens on (known once it has started).</summary>
    private static async Task<EmbeddedController> StartAsync<TState>(VirtualController<TState> controller, Func<int> port, CancellationToken cancellationToken)
        where TState : VirtualRobotState
    {
        await controller.StartAsync(cancellationToken).ConfigureAwait(false);
        return new EmbeddedController(port(), controller);
    }
}
