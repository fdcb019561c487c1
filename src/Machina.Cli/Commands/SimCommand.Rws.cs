using System.Net;
using Machina.Cli.Simulation;
using Machina.Simulation;
using Machina.Simulation.Rws;

namespace Machina.Cli.Commands;

/// <summary><c>machina sim abb</c>: Robot Web Services in front of the virtual ABB's RAPID tasks, on the port the log names.</summary>
internal static partial class SimCommand
{
    /// <summary>
    /// Starts Robot Web Services for the virtual ABB's RAPID twin, reachable on <paramref name="bind"/> at <paramref name="port"/>
    /// (read only when the controller runs RAPID; 0: a free one), and names the port through <paramref name="announce"/> (the relay's events go to <paramref name="log"/>); null
    /// when the controller runs no RAPID. Disposing stops both.
    /// </summary>
    private static IAsyncDisposable? StartRws(RunningController controller, IPAddress bind, Func<int> port, Action<string> log, Action<string> announce)
    {
        return controller.Inner.Controller is VirtualAbbController { Twin: { } twin } ? StartRws(twin, bind, port(), log, announce) : null;
    }

    /// <summary>Starts Robot Web Services for <paramref name="twin"/> (see above), reachable on <paramref name="bind"/> at <paramref name="port"/>.</summary>
    internal static IAsyncDisposable StartRws(Machina.Simulation.Rapid.RapidTwinController twin, IPAddress bind, int port, Action<string> log, Action<string> announce)
    {
        var server = new RwsTwinServer(twin);
        server.Start();
        TcpRelay relay;
        try
        {
            relay = TcpRelay.Start(bind, port, [new RelayRoute(0, server.Port, "RWS")], log);
        }
        catch
        {
            server.DisposeAsync().AsTask().GetAwaiter().GetResult();
            throw;
        }
        announce($"Robot Web Services (RWS 1.0) on {bind}:{relay.Port}, user \"Default User\", password \"robotics\"; e.g. " +
            $"machina drivers abb --install --host {(bind.Equals(IPAddress.Any) ? "127.0.0.1" : bind.ToString())} --rws-port {relay.Port} --port {DefaultPort + 100}");
        announce($"RWS's /fileservice/$HOME is RAPID's HOME:, the folder {twin.HomeDirectory}.");
        return new RwsEndpoint(server, relay);
    }

    /// <summary>The RWS server and its relay, stopped together.</summary>
    private sealed class RwsEndpoint(RwsTwinServer server, TcpRelay relay) : IAsyncDisposable
    {
        public async ValueTask DisposeAsync()
        {
            await relay.DisposeAsync().ConfigureAwait(false);
            await server.DisposeAsync().ConfigureAwait(false);
        }
    }
}
