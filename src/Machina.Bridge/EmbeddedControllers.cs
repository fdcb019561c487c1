using Machina.Simulation;

namespace Machina.Bridge;

/// <summary>A virtual controller running inside the bridge, the loopback port its driver listens on, and the arm it moves like.</summary>
internal sealed record EmbeddedController(int Port, IAsyncDisposable Owner, RobotModel? Model);

/// <summary>
/// The virtual controllers the bridge can start in place of a real one: those of <see cref="VirtualControllerRegistry"/>, so that a
/// brand with a virtual controller works in the bridge without a line here.
/// </summary>
internal static class EmbeddedControllers
{
    /// <summary>
    /// Larger arms the bridge's virtual controllers move like instead of their brand's default, where the default cannot reach the
    /// paper's Hello Robot (an IRB 1200-5/0.9 reaches it, an IRB 120 does not).
    /// </summary>
    private static readonly string[] DemoModels = ["IRB 1200-5/0.9"];

    /// <summary>Starts a virtual controller for a brand, or null when Machina has none for it yet.</summary>
    internal static Func<BridgeOptions, CancellationToken, Task<EmbeddedController>>? For(RobotType brand) =>
        VirtualControllerRegistry.Has(brand) ? (options, cancellationToken) => StartAsync(brand, options, cancellationToken) : null;

    private static async Task<EmbeddedController> StartAsync(RobotType brand, BridgeOptions options, CancellationToken cancellationToken)
    {
        VirtualControllerOptions settings = VirtualControllerRegistry.DefaultOptions(brand) with
        {
            SpeedFactor = options.SimulationSpeed,
            TimeProvider = options.TimeProvider,
        };
        string? catalogueBrand = BrandRegistry.For(brand).ModelBrand;
        if (DemoModels.Select(RobotModels.Get).FirstOrDefault(m => m.Brand == catalogueBrand) is RobotModel demo)
        {
            settings = settings with { Model = demo };
        }
        RunningVirtualController controller = await VirtualControllerRegistry.StartAsync(brand, settings, cancellationToken).ConfigureAwait(false);
        return new EmbeddedController(controller.Port, controller.Controller, controller.Model);
    }
}
