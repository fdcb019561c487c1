using Machina.Simulation;

namespace Machina.Cli.Simulation;

/// <summary>How a virtual controller started by the command line behaves.</summary>
/// <param name="SpeedFactor">How much faster than real time it moves (1 = real time).</param>
/// <param name="Model">The arm it moves like, or null (joints and pose then stay independent).</param>
internal sealed record VirtualControllerOptions(double SpeedFactor = 1, RobotModel? Model = null);

/// <summary>A virtual controller listening on 127.0.0.1, until disposed.</summary>
internal sealed class RunningController(RobotType brand, int port, int[] ports, string[] portNames, Func<ValueTask> stop, Func<string> summary,
    Func<ControllerView> look) : IAsyncDisposable
{
    /// <summary>The brand whose driver it imitates.</summary>
    internal RobotType Brand { get; } = brand;

    /// <summary>Where a Machina host connects: always 127.0.0.1.</summary>
    internal string Host => "127.0.0.1";

    /// <summary>The port a Machina host connects to.</summary>
    internal int Port { get; } = port;

    /// <summary>Every port it listens on, as offsets from <see cref="Port"/> (ABB: 0 for the driver, 1 for the monitor).</summary>
    internal int[] PortOffsets { get; } = ports;

    /// <summary>What each port is for (ABB: "driver", "monitor"; UR: "script", "RTDE", "dashboard"), in the order of <see cref="PortOffsets"/>.</summary>
    internal string[] PortNames { get; } = portNames;

    /// <summary>What it did: requests received and executed.</summary>
    internal string Summary() => summary();

    /// <summary>What it shows of itself now: requests, executed actions, pendant, errors, robot and outputs.</summary>
    internal ControllerView Look() => look();

    /// <summary>Stops it and closes its connections.</summary>
    public ValueTask DisposeAsync() => stop();
}

/// <summary>
/// THE place where the command line starts virtual controllers, for <c>machina sim BRAND</c> and <c>machina run --sim</c>.
/// Adding a brand is one line in <see cref="StartAsync"/> once its virtual controller exists in Machina.Simulation.
/// </summary>
internal static class VirtualControllers
{
    /// <summary>The brands that have a virtual controller in this build.</summary>
    internal static readonly RobotType[] Available = [RobotType.ABB, RobotType.UR, RobotType.KUKA];

    /// <summary>The brands of <see cref="Available"/> as typed on the command line, e.g. "abb, ur, kuka", for help texts.</summary>
    internal static string AvailableNames => string.Join(", ", Available.Select(Brands.Name));

    /// <summary>Starts a virtual controller of <paramref name="brand"/> on 127.0.0.1 (an OS-chosen port).</summary>
    /// <exception cref="CliException">This build has no virtual controller for the brand.</exception>
    internal static async Task<RunningController> StartAsync(RobotType brand, VirtualControllerOptions options, CancellationToken cancellationToken) => brand switch
    {
        RobotType.ABB => await StartAbbAsync(options, cancellationToken).ConfigureAwait(false),
        RobotType.KUKA => await StartKukaAsync(options, cancellationToken).ConfigureAwait(false),
        RobotType.UR => await StartUrAsync(options, cancellationToken).ConfigureAwait(false),
        _ => throw new UsageException($"{brand} devices have no virtual controller: only robot arms (abb, ur, kuka) are controlled online."),
    };

    /// <summary>The error for an arm brand whose online control is still being built.</summary>
    internal static CliException NotInThisBuild(RobotType brand) => new(
        $"Online control of {brand} robots (and its virtual controller) is not available in this build yet; " +
        $"only {string.Join(", ", Available.Select(b => b.ToString()))} is. Compile the program instead: machina compile PROGRAM --brand {Brands.Name(brand)}");

    private static async Task<RunningController> StartAbbAsync(VirtualControllerOptions options, CancellationToken cancellationToken)
    {
        var controller = new VirtualAbbController(Settings(new VirtualAbbControllerOptions(), options));
        await controller.StartAsync(cancellationToken).ConfigureAwait(false);
        return new RunningController(RobotType.ABB, controller.Port, [0, 1], ["driver", "monitor"], controller.DisposeAsync,
            () => $"{controller.RequestsReceived} requests received, {controller.RequestsExecuted} executed, {controller.Errors.Count} malformed",
            () => ControllerView.Of(controller));
    }

    private static async Task<RunningController> StartUrAsync(VirtualControllerOptions options, CancellationToken cancellationToken)
    {
        var controller = new VirtualUrController(Settings(new VirtualUrControllerOptions(), options));
        await controller.StartAsync(cancellationToken).ConfigureAwait(false);
        return new RunningController(RobotType.UR, controller.Port, [0, 1, 2], ["script", "RTDE", "dashboard"], controller.DisposeAsync,
            () => $"{controller.RequestsReceived} instructions received, {controller.RequestsExecuted} executed, {controller.Errors.Count} refused",
            () => ControllerView.Of(controller));
    }

    private static async Task<RunningController> StartKukaAsync(VirtualControllerOptions options, CancellationToken cancellationToken)
    {
        var controller = new VirtualKukaController(Settings(new VirtualKukaControllerOptions(), options));
        await controller.StartAsync(cancellationToken).ConfigureAwait(false);
        return new RunningController(RobotType.KUKA, controller.Port, [0, 1], ["driver", "monitor"], controller.DisposeAsync,
            () => $"{controller.RequestsReceived} requests received, {controller.RequestsExecuted} executed, {controller.Errors.Count} refused",
            () => ControllerView.Of(controller));
    }

    /// <summary>Requests (and executed ids) a command-line controller keeps for telling what it does.</summary>
    internal const int RequestsKept = 4096;

    /// <summary>
    /// A brand's default settings with the command line's speed and arm (the brand's default arm when none is given), keeping the
    /// last <see cref="RequestsKept"/> requests and executed ids for <see cref="ControllerActivity"/> (bounded, whatever the program's length).
    /// </summary>
    private static T Settings<T>(T defaults, VirtualControllerOptions options) where T : Machina.Simulation.VirtualControllerOptions
    {
        Machina.Simulation.VirtualControllerOptions settings = defaults;
        settings = settings with { SpeedFactor = options.SpeedFactor, RequestLogCapacity = RequestsKept };
        if (options.Model is RobotModel model)
        {
            settings = settings with { Model = model };
        }
        return (T)settings;
    }
}
