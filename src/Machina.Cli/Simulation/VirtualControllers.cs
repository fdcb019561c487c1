using Machina.Simulation;

namespace Machina.Cli.Simulation;

/// <summary>How a virtual controller started by the command line behaves.</summary>
/// <param name="SpeedFactor">How much faster than real time it moves (1 = real time).</param>
/// <param name="Model">The arm it moves like, or null (joints and pose then stay independent).</param>
/// <param name="VendorSimulator">
/// It stands in for the vendor's own simulator where the brand has one (UR: URSim, with its client interfaces, powered off at
/// the start; <see cref="VirtualControllerRegistry.VendorPorts"/>).
/// </param>
/// <param name="Home">The controller's mass memory (ABB: RAPID's HOME:, RWS's $HOME), or null for a new temporary folder.</param>
internal sealed record VirtualControllerOptions(double SpeedFactor = 1, RobotModel? Model = null, bool VendorSimulator = false, string? Home = null)
{
    /// <summary>
    /// Where it listens itself, for a brand whose controller can (<see cref="VirtualControllerRegistry.ListensWhereAsked"/>): the
    /// address and the first port (0: the system chooses); null: on 127.0.0.1 at ports the system chooses.
    /// </summary>
    public (System.Net.IPAddress Address, int Port)? Listen { get; init; }

    /// <summary>Told of each host that connects to a port (its name, the host, true) and leaves it (false), where it listens itself.</summary>
    public Action<string, string, bool>? ConnectionSeen { get; init; }
}

/// <summary>A virtual controller listening on 127.0.0.1, until disposed: one of <see cref="VirtualControllerRegistry"/>, as the command line shows it.</summary>
internal sealed class RunningController(RunningVirtualController controller) : IAsyncDisposable
{
    /// <summary>The controller itself (for the ABB's Robot Web Services, which act on its RAPID twin).</summary>
    internal RunningVirtualController Inner => controller;

    /// <summary>The brand whose driver it imitates.</summary>
    internal RobotType Brand => controller.Brand;

    /// <summary>Where a Machina host connects: always 127.0.0.1.</summary>
    internal string Host => "127.0.0.1";

    /// <summary>The port a Machina host connects to.</summary>
    internal int Port => controller.Port;

    /// <summary>Every port it listens on, as offsets from <see cref="Port"/> (ABB: 0 for the driver, 1 for the monitor).</summary>
    internal int[] PortOffsets => [.. controller.Ports.Select(p => p - controller.Port)];

    /// <summary>What each port is for (ABB: "driver", "monitor"; UR: "script", "RTDE", "dashboard", and "primary", "secondary", "real-time" when served), in the order of <see cref="PortOffsets"/>.</summary>
    internal string[] PortNames => [.. controller.PortNames];

    /// <summary>Every port it listens on, on 127.0.0.1, in the order of <see cref="PortNames"/>.</summary>
    internal int[] Ports => [.. controller.Ports];

    /// <summary>Relays to every port, each at its offset from the first (the compact layout of <c>--port P</c>).</summary>
    internal RelayRoute[] CompactRoutes => [.. Ports.Select((p, i) => new RelayRoute(p - Port, p, PortNames[i]))];

    /// <summary>What it did: requests received and executed.</summary>
    internal string Summary() => controller.Summary();

    /// <summary>Stops it and closes its connections.</summary>
    public ValueTask DisposeAsync() => controller.DisposeAsync();
}

/// <summary>
/// Where the command line starts virtual controllers, for <c>machina sim BRAND</c> and <c>machina run --sim</c>: those of
/// <see cref="VirtualControllerRegistry"/>, with the command line's speed and arm.
/// </summary>
internal static class VirtualControllers
{
    /// <summary>The brands that have a virtual controller in this build.</summary>
    internal static IReadOnlyList<RobotType> Available => VirtualControllerRegistry.Brands;

    /// <summary>The brands of <see cref="Available"/> as typed on the command line, e.g. "abb, ur, kuka", for help texts.</summary>
    internal static string AvailableNames => string.Join(", ", Available.Select(Brands.Name));

    /// <summary>Starts a virtual controller of <paramref name="brand"/> on 127.0.0.1 (an OS-chosen port).</summary>
    /// <exception cref="CliException">This build has no virtual controller for the brand.</exception>
    internal static async Task<RunningController> StartAsync(RobotType brand, VirtualControllerOptions options, CancellationToken cancellationToken)
    {
        if (!VirtualControllerRegistry.Has(brand))
        {
            throw new UsageException($"{brand} devices have no virtual controller: only robot arms ({AvailableNames}) are controlled online.");
        }
        RunningVirtualController controller = await VirtualControllerRegistry.StartAsync(
            brand, Settings(brand, VirtualControllerRegistry.DefaultOptions(brand), options), cancellationToken).ConfigureAwait(false);
        return new RunningController(controller);
    }

    /// <summary>The error for an arm brand whose online control is still being built.</summary>
    internal static CliException NotInThisBuild(RobotType brand) => new(
        $"Online control of {brand} robots (and its virtual controller) is not available in this build yet; " +
        $"only {string.Join(", ", Available.Select(b => b.ToString()))} is. Compile the program instead: machina compile PROGRAM --brand {Brands.Name(brand)}");

    /// <summary>Requests (and executed ids) a command-line controller keeps for telling what it does.</summary>
    internal const int RequestsKept = 4096;

    /// <summary>
    /// A brand's default settings with the command line's speed and arm (the brand's default arm when none is given), keeping the
    /// last <see cref="RequestsKept"/> requests and executed ids for <see cref="ControllerActivity"/> (bounded, whatever the program's length).
    /// </summary>
    private static Machina.Simulation.VirtualControllerOptions Settings(RobotType brand, Machina.Simulation.VirtualControllerOptions defaults, VirtualControllerOptions options)
    {
        Machina.Simulation.VirtualControllerOptions settings = defaults;
        settings = settings with { SpeedFactor = options.SpeedFactor, RequestLogCapacity = RequestsKept };
        if (options.VendorSimulator)
        {
            settings = VirtualControllerRegistry.AsVendorSimulator(brand, settings);
        }
        if (options.Home is { } home)
        {
            settings = VirtualControllerRegistry.WithHome(brand, settings, home);
        }
        if (options.Model is RobotModel model)
        {
            settings = settings with { Model = model };
        }
        if (options.Listen is { } listen)
        {
            settings = settings with { ListenAddress = listen.Address, ListenPort = listen.Port, ConnectionSeen = options.ConnectionSeen };
        }
        return settings;
    }
}
