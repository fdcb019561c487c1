// Shared by the online samples (linked into each project): which robot, and where it is, from the command line.
using Machina;
using Machina.Simulation;

/// <summary>
/// The controller an online sample talks to: a virtual controller started on this computer (ABB by default, another brand
/// with <c>--brand</c>, e.g. <c>--brand ur</c>; see <c>VirtualControllerRegistry</c>), or a real one given with <c>--host</c> and <c>--port</c> (running
/// Machina's driver: RAPID on ABB, KRL on KUKA; on UR the script port, 30003, to which Machina sends its URScript driver).
/// </summary>
internal sealed class SampleController : IAsyncDisposable
{
    /// <summary>
    /// A larger arm than the brand's default for the virtual controller, where the default cannot reach the paper's Hello Robot
    /// targets (an IRB 1200-5/0.9 reaches them, the virtual ABB's default IRB 120 does not).
    /// </summary>
    private const string DemoModel = "IRB 1200-5/0.9";

    private readonly RunningVirtualController? _simulator;

    private SampleController(RobotType brand, string host, int port, RunningVirtualController? simulator)
    {
        Brand = brand;
        Host = host;
        Port = port;
        _simulator = simulator;
    }

    /// <summary>The robot brand, as <c>Robot.Create</c> takes it: the first brand with a virtual controller (ABB) unless <c>--brand</c> says otherwise.</summary>
    public RobotType Brand { get; }

    /// <summary>Address of the controller.</summary>
    public string Host { get; }

    /// <summary>Port of the Machina driver on the controller (UR: the script port).</summary>
    public int Port { get; }

    /// <summary>
    /// Reads <c>--brand</c>, <c>--host</c>, <c>--port</c>, <c>--speed-factor</c> and the sample's own options (<paramref name="option"/>
    /// takes a name and a value and says whether it knew them), then starts a virtual controller when no host was given, running
    /// <paramref name="speedFactor"/> times faster than real time unless <c>--speed-factor</c> says otherwise. Null (after printing
    /// <paramref name="usage"/> on <paramref name="error"/>) when the arguments are wrong.
    /// </summary>
    public static async Task<SampleController?> OpenAsync(string[] args, string usage, double speedFactor, TextWriter output, TextWriter error,
        Func<string, string, bool>? option = null, CancellationToken cancellationToken = default)
    {
        string? host = null;
        RobotType brand = VirtualControllerRegistry.Brands[0];
        int port = 0;
        for (int i = 0; i < args.Length; i++)
        {
            string? value = i + 1 < args.Length ? args[i + 1] : null;
            bool known = value is not null && args[i] switch
            {
                "--host" => (host = value) is not null,
                "--port" => int.TryParse(value, out port) && port is > 0 and <= 65535,
                "--brand" => TryBrand(value, ref brand),
                "--speed-factor" => double.TryParse(value, System.Globalization.CultureInfo.InvariantCulture, out speedFactor) && speedFactor is > 0 and <= 1000,
                _ => option?.Invoke(args[i], value) ?? false,
            };
            if (!known)
            {
                error.WriteLine("Usage: " + usage + " [--speed-factor <times faster than real time>]");
                return null;
            }
            i++;
        }
        if (host is not null)
        {
            return new SampleController(brand, host, port != 0 ? port : VirtualControllerRegistry.DriverPort(brand), null);
        }
        VirtualControllerOptions settings = VirtualControllerRegistry.DefaultOptions(brand) with { SpeedFactor = speedFactor };
        if (RobotModels.Get(DemoModel) is { } demo && demo.Brand == settings.Model?.Brand)
        {
            settings = settings with { Model = demo };
        }
        RunningVirtualController controller = await VirtualControllerRegistry.StartAsync(brand, settings, cancellationToken);
        string ports = string.Join(", ", controller.PortNames.Zip(controller.Ports, (name, p) => $"{name} on {p}"));
        output.WriteLine($"Started a virtual {brand} {controller.Model?.Name} controller on 127.0.0.1 ({ports}; {speedFactor}x faster than real time).");
        return new SampleController(brand, "127.0.0.1", controller.Port, controller);
    }

    /// <summary>Sets <paramref name="brand"/> to the brand named <paramref name="name"/> (any letter case) when it has a virtual controller.</summary>
    private static bool TryBrand(string name, ref RobotType brand)
    {
        if (VirtualControllerRegistry.Find(name) is not RobotType named)
        {
            return false;
        }
        brand = named;
        return true;
    }

    /// <summary>What the virtual controller refused (e.g. a target its robot cannot reach); empty for a real controller.</summary>
    public IReadOnlyList<string> Errors => _simulator?.Errors ?? [];

    /// <summary>The virtual controller's robot as it is now (pose, joints, tool, outputs); null for a real controller.</summary>
    public VirtualRobotState? State => _simulator?.State;

    /// <summary>
    /// The arm of the virtual controller (null for a real controller: give your robot's model yourself). A robot created with it
    /// knows its pose after joint moves and its joints after Cartesian moves.
    /// </summary>
    public RobotModel? Model => _simulator?.Model;

    /// <summary>Stops the virtual controller, if one was started.</summary>
    public ValueTask DisposeAsync() => _simulator?.DisposeAsync() ?? ValueTask.CompletedTask;
}
