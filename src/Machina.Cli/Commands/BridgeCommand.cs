namespace Machina.Cli.Commands;

/// <summary>
/// <c>machina bridge</c>: the Machina Bridge (a web page and WebSocket server between apps and a robot). It lives in the
/// Machina.Bridge library, which is not part of this build yet: <see cref="RunAsync"/> is the one place to wire its BridgeServer.
/// </summary>
internal static class BridgeCommand
{
    internal static readonly CliCommand Command = new(
        "bridge",
        "Run the Machina Bridge (not in this build)",
        """
        Usage: machina bridge

        The Machina Bridge connects apps (Grasshopper, Dynamo, a web page) to a robot over WebSockets. It is not in this
        build of the machina tool yet.
        """,
        Options: [],
        Flags: [],
        RunAsync);

    private static Task<int> RunAsync(CliArgs args, CliContext context)
    {
        // Wire Machina.Bridge's BridgeServer here: read the listen endpoint, the brand and --sim or --host/--port from args,
        // StartAsync it, wait for context.Cancellation, then StopAsync.
        throw new CliException("machina bridge is not in this build yet: the Machina Bridge is being built separately.");
    }
}
