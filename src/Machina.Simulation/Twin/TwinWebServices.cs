namespace Machina.Simulation.Twin;

/// <summary>
/// A controller's web services as its twin serves them on 127.0.0.1 (ABB: Robot Web Services in front of the RAPID tasks): where
/// they listen, how a client logs on, and what else a person starting them should know. Disposing stops them.
/// </summary>
/// <param name="Port">The loopback port they listen on.</param>
/// <param name="Name">What they are, as a log line names them (e.g. "Robot Web Services (RWS 1.0)").</param>
/// <param name="LogOn">How a client logs on (e.g. the default user and password).</param>
/// <param name="Notes">Further lines for the log (e.g. where the controller's mass memory is).</param>
/// <param name="Server">The server to stop.</param>
internal sealed record TwinWebServices(int Port, string Name, string LogOn, IReadOnlyList<string> Notes, IAsyncDisposable Server) : IAsyncDisposable
{
    /// <summary>Stops the services and closes their connections.</summary>
    public ValueTask DisposeAsync() => Server.DisposeAsync();
}
