using System.Net;
using Machina.Simulation;
using Machina.Simulation.Twin;

namespace Machina.Cli.Simulation;

/// <summary>
/// <c>machina sim</c>: a virtual controller's web services (ABB: Robot Web Services in front of its RAPID tasks), relayed to the
/// address and port the command asks for, and named in its log with how to log on and, for a brand whose driver Machina installs
/// through them, the command that does.
/// </summary>
internal static class SimWebServices
{
    /// <summary>
    /// Starts the web services of <paramref name="controller"/>'s brand, reachable on <paramref name="bind"/> at <paramref name="port"/>
    /// (read only when the controller serves some; 0: a free one); null when it serves none. Disposing stops them.
    /// </summary>
    internal static IAsyncDisposable? Start(RunningController controller, IPAddress bind, Func<int> port, int driverPort, Action<string> log, Action<string> announce) =>
        VirtualControllerRegistry.StartWebServices(controller.Inner) is { } services
            ? Relay(controller.Brand, services, bind, port(), driverPort, log, announce)
            : null;

    /// <summary>
    /// Makes <paramref name="services"/> (started by the caller, stopped with the result) reachable on <paramref name="bind"/> at
    /// <paramref name="port"/> (0: a free one), and names them through <paramref name="announce"/> (the relay's events go to <paramref name="log"/>).
    /// </summary>
    internal static IAsyncDisposable Relay(RobotType brand, TwinWebServices services, IPAddress bind, int port, int driverPort, Action<string> log, Action<string> announce)
    {
        TcpRelay relay;
        try
        {
            relay = TcpRelay.Start(bind, port, [new RelayRoute(0, services.Port, "RWS")], log);
        }
        catch
        {
            services.DisposeAsync().AsTask().GetAwaiter().GetResult();
            throw;
        }
        string host = bind.Equals(IPAddress.Any) ? "127.0.0.1" : bind.ToString();
        string line = $"{services.Name} on {bind}:{relay.Port}, {services.LogOn}";
        announce(BrandRegistry.For(brand).InstallDriver is null ? line + "."
            : $"{line}; e.g. machina drivers {Brands.Name(brand)} --install --host {host} --rws-port {relay.Port} --port {driverPort}");
        foreach (string note in services.Notes)
        {
            announce(note);
        }
        return new Endpoint(services, relay);
    }

    /// <summary>The services and their relay, stopped together.</summary>
    private sealed class Endpoint(TwinWebServices services, TcpRelay relay) : IAsyncDisposable
    {
        public async ValueTask DisposeAsync()
        {
            await relay.DisposeAsync().ConfigureAwait(false);
            await services.DisposeAsync().ConfigureAwait(false);
        }
    }
}
