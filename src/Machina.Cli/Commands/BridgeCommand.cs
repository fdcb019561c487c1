using System.Net;
using Machina.Bridge;

namespace Machina.Cli.Commands;

/// <summary>
/// <c>machina bridge</c>: the Machina Bridge, a web page and WebSocket server between apps (Grasshopper, Dynamo, Processing,
/// Python, a browser) and one robot, real or virtual. The server itself is <see cref="BridgeServer"/> in Machina.Bridge.
/// </summary>
internal static class BridgeCommand
{
    internal static readonly CliCommand Command = new(
        "bridge",
        "Run the Machina Bridge: apps and a web page drive a robot over WebSockets",
        $"""
        Usage: machina bridge [--listen ADDRESS:PORT] [--token T] [--brand abb|ur|kuka] (--sim | --host H --port P) [--speed-factor F]

        Starts the Machina Bridge until Ctrl+C: the original Machina clients (Grasshopper, Dynamo, Processing, Python,
        JavaScript) connect to ws://ADDRESS:PORT{BridgeOptions.DefaultPath} unchanged, and a browser at http://ADDRESS:PORT/
        shows a page to type instructions and watch the tool path. Every message sent to the bridge is issued on one robot,
        online: a virtual controller on this computer (--sim, the default) or a real one (--host and --port).

        Options:
          --listen ADDRESS:PORT  where the bridge listens (default 127.0.0.1:{BridgeOptions.DefaultPort}, this computer only)
          --token T              a secret clients must pass as authkey=T in their address (required when --listen is
                                 not a loopback address); open the page at http://ADDRESS:PORT/?authkey=T
          --brand B              abb (default), ur or kuka
          --sim                  drive a virtual controller started on this computer (the default)
          --host H --port P      drive a real controller running Machina's driver
          --speed-factor F       with --sim: how much faster than real time the virtual robot moves (default 1)

        Example:
          machina bridge --sim
          (then open http://127.0.0.1:{BridgeOptions.DefaultPort}/ in a browser)
        """,
        Options: ["--listen", "--token", "--brand", "--host", "--port", "--speed-factor"],
        Flags: ["--sim"],
        RunAsync);

    private static async Task<int> RunAsync(CliArgs args, CliContext context)
    {
        string listenText = args.Value("--listen") ?? $"127.0.0.1:{BridgeOptions.DefaultPort}";
        if (!IPEndPoint.TryParse(listenText, out IPEndPoint? listen))
        {
            throw new UsageException($"--listen needs an address and a port such as 127.0.0.1:{BridgeOptions.DefaultPort}, not \"{listenText}\".");
        }
        RobotType brand = args.Value("--brand") is string b
            ? Brands.Parse(b, Brands.Online, "bridge")
            : BrandRegistry.DefaultOnline.Type;
        string? host = args.Value("--host");
        if (host is not null && args.Has("--sim"))
        {
            throw new UsageException("Choose --sim or --host, not both.");
        }
        int port = host is null ? 0 : args.Port("--port", BrandRegistry.For(brand).DefaultPort);
        var options = new BridgeOptions
        {
            Listen = listen,
            Brand = brand,
            ControllerHost = host,
            ControllerPort = host is null ? new BridgeOptions().ControllerPort : port,
            SimulationSpeed = args.Positive("--speed-factor", 1),
            Token = args.Value("--token"),
        };
        BridgeServer created;
        try
        {
            created = new BridgeServer(options);
        }
        catch (ArgumentException ex) when (ex.ParamName == nameof(BridgeOptions.Token))
        {
            throw new UsageException(ex.Message[..(ex.Message.IndexOf(" (Parameter", StringComparison.Ordinal) is int i and >= 0 ? i : ex.Message.Length)]);
        }
        await using var bridge = created;
        bridge.Robot.Logger.Writer = context.Stderr;
        try
        {
            await bridge.StartAsync(context.Cancellation).ConfigureAwait(false);
        }
        catch (System.Net.Sockets.SocketException ex)
        {
            throw new CliException($"The bridge cannot listen on {listen}: {ex.Message}");
        }
        catch (MachinaException ex)
        {
            throw new CliException($"The bridge cannot reach the {brand} controller: {ex.Message}");
        }
        string key = options.Token is null ? "" : "?authkey=" + options.Token;
        await context.Stdout.WriteLineAsync($"Machina Bridge for a {(host is null ? "virtual" : "real")} {brand} robot: apps connect to {bridge.WebSocketUri}{key}, "
            + $"the page is at {bridge.PageUri}{key}. Press Ctrl+C to stop.").ConfigureAwait(false);
        context.Ready?.Invoke(bridge.WebSocketUri!.ToString());
        try
        {
            await Task.Delay(Timeout.Infinite, context.Cancellation).ConfigureAwait(false);
        }
        catch (OperationCanceledException)
        {
        }
        await bridge.StopAsync().ConfigureAwait(false);
        await context.Stdout.WriteLineAsync("Bridge stopped.").ConfigureAwait(false);
        return ExitCodes.Ok;
    }
}
