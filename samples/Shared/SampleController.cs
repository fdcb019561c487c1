// Shared by the online samples (linked into each project): where the robot is, from the command line.
using Machina.Simulation;

/// <summary>
/// The controller an online sample talks to: a virtual controller started on this computer (ABB by default, KUKA with
/// <c>--brand kuka</c>), or a real one given with <c>--host</c> and <c>--port</c> (running Machina's driver).
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

    /// <summary>The robot brand, as <c>Robot.Create</c> takes it ("ABB" unless <c>--brand</c> says otherwise).</summary>
    public string Brand { get; }

    /// <summary>Address of the controller.</summary>
    public string Host { get; }

    /// <summary>Port of the Machina driver on the controller.</summary>
    public int Port { get; }

    /// <summary>
    /// Reads <c>--host</c>, <c>--port</c> and the sample's own options (<paramref name="option"/> takes a name and a value and
    /// says whether it knew them), then starts a virtual controller when no host was given. Null (after printing
    /// <paramref name="usage"/>) when the arguments are wrong.
    /// </summary>
    public static async Task<SampleController?> OpenAsync(string[] args, string usage, double speedFactor, Func<string, string, bool>? option = null)
    {
        string? host = null;
        int port = 7000;
        string brand = "ABB";
        for (int i = 0; i < args.Length; i++)
        {
            string? value = i + 1 < args.Length ? args[i + 1] : null;
            bool known = value is not null && args[i] switch
            {
                "--host" => (host = value) is not null,
                "--port" => int.TryParse(value, out port) && port is > 0 and <= 65535,
                "--brand" => (brand = value.ToUpperInvariant()) is "ABB" or "KUKA",
                _ => option?.Invoke(args[i], value) ?? false,
            };
            if (!known)
            {
                Console.Error.WriteLine("Usage: " + usage);
                return null;
            }
            i++;
        }
        if (host is not null)
        {
            return new SampleController(brand, host, port, null);
        }
        if (brand == "KUKA")
        {
            var kuka = new VirtualKukaController(new VirtualKukaControllerOptions { SpeedFactor = speedFactor });
            await kuka.StartAsync();
            Console.WriteLine($"Started a virtual KUKA controller (KR 6 R900 sixx) on 127.0.0.1:{kuka.Port} ({speedFactor}x faster than real time).");
            return new SampleController(brand, "127.0.0.1", kuka.Port, kuka);
        }
        var simulator = new VirtualAbbController(new VirtualAbbControllerOptions { SpeedFactor = speedFactor });
        await simulator.StartAsync();
        Console.WriteLine($"Started a virtual ABB controller on 127.0.0.1:{simulator.Port} ({speedFactor}x faster than real time).");
        return new SampleController(brand, "127.0.0.1", simulator.Port, simulator);
    }

    /// <summary>Stops the virtual controller, if one was started.</summary>
    public ValueTask DisposeAsync() => _simulator?.DisposeAsync() ?? ValueTask.CompletedTask;
}
