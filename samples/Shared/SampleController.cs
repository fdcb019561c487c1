// Shared by the online samples (linked into each project): which robot, and where it is, from the command line.
using Machina;
using Machina.Simulation;

/// <summary>
/// The controller an online sample talks to: a virtual controller started on this computer (ABB by default, UR with
/// <c>--brand ur</c>, KUKA with <c>--brand kuka</c>), or a real one given with <c>--host</c> and <c>--port</c> (running
/// Machina's driver: RAPID on ABB, KRL on KUKA; on UR the script port, 30003, to which Machina sends its URScript driver).
/// </summary>
internal sealed class SampleController : IAsyncDisposable
{
    private readonly IAsyncDisposable? _simulator;

    private SampleController(string brand, string host, int port, IAsyncDisposable? simulator)
    {
        Brand = brand;
        Host = host;
        Port = port;
        _simulator = simulator;
    }

    /// <summary>The robot brand, as <c>Robot.Create</c> takes it: "ABB" (the default), "UR" or "KUKA".</summary>
    public string Brand { get; }

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
        string brand = "ABB";
        int port = 0;
        for (int i = 0; i < args.Length; i++)
        {
            string? value = i + 1 < args.Length ? args[i + 1] : null;
            bool known = value is not null && args[i] switch
            {
                "--host" => (host = value) is not null,
                "--port" => int.TryParse(value, out port) && port is > 0 and <= 65535,
                "--brand" => (brand = value.ToUpperInvariant()) is "ABB" or "UR" or "KUKA",
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
            return new SampleController(brand, host, port != 0 ? port : brand == "UR" ? 30003 : 7000, null);
        }
        if (brand == "UR")
        {
            var ur = new VirtualUrController(new VirtualUrControllerOptions { SpeedFactor = speedFactor });
            await StartedAsync(ur, ur.StartAsync(cancellationToken));
            output.WriteLine($"Started a virtual UR5e controller on 127.0.0.1 (scripts on {ur.Port}, RTDE on {ur.RtdePort}, dashboard on {ur.DashboardPort}; {speedFactor}x faster than real time).");
            return new SampleController(brand, "127.0.0.1", ur.Port, ur);
        }
        if (brand == "KUKA")
        {
            var kuka = new VirtualKukaController(new VirtualKukaControllerOptions { SpeedFactor = speedFactor });
            await StartedAsync(kuka, kuka.StartAsync(cancellationToken));
            output.WriteLine($"Started a virtual KUKA controller (KR 6 R900 sixx) on 127.0.0.1:{kuka.Port} ({speedFactor}x faster than real time).");
            return new SampleController(brand, "127.0.0.1", kuka.Port, kuka);
        }
        // An IRB 1200-5/0.9 (the virtual ABB's default, an IRB 120, cannot reach the paper's Hello Robot targets).
        var abb = new VirtualAbbController(new VirtualAbbControllerOptions { SpeedFactor = speedFactor, Model = RobotModels.Get("IRB 1200-5/0.9") });
        await StartedAsync(abb, abb.StartAsync(cancellationToken));
        output.WriteLine($"Started a virtual ABB IRB 1200-5/0.9 controller on 127.0.0.1:{abb.Port} ({speedFactor}x faster than real time).");
        return new SampleController(brand, "127.0.0.1", abb.Port, abb);
    }

    /// <summary>Waits for a virtual controller to start, and stops it again if it could not (e.g. no free port).</summary>
    private static async Task StartedAsync(IAsyncDisposable controller, Task starting)
    {
        try
        {
            await starting;
        }
        catch
        {
            await controller.DisposeAsync();
            throw;
        }
    }

    /// <summary>What the virtual controller refused (e.g. a target its robot cannot reach); empty for a real controller.</summary>
    public IReadOnlyList<string> Errors => _simulator switch
    {
        VirtualAbbController abb => abb.Errors,
        VirtualUrController ur => ur.Errors,
        VirtualKukaController kuka => kuka.Errors,
        _ => [],
    };

    /// <summary>The virtual controller's robot as it is now (pose, joints, tool, outputs); null for a real controller.</summary>
    public VirtualRobotState? State => _simulator switch
    {
        VirtualAbbController abb => abb.State,
        VirtualUrController ur => ur.State,
        VirtualKukaController kuka => kuka.State,
        _ => null,
    };

    /// <summary>
    /// The arm of the virtual controller (null for a real controller: give your robot's model yourself). A robot created with it
    /// knows its pose after joint moves and its joints after Cartesian moves.
    /// </summary>
    public RobotModel? Model => _simulator switch
    {
        VirtualAbbController abb => abb.Model,
        VirtualUrController ur => ur.Model,
        VirtualKukaController kuka => kuka.Model,
        _ => null,
    };

    /// <summary>Stops the virtual controller, if one was started.</summary>
    public ValueTask DisposeAsync() => _simulator?.DisposeAsync() ?? ValueTask.CompletedTask;
}
