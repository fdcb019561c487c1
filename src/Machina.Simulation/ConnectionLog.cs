using System.Net.Sockets;

namespace Machina.Simulation;

/// <summary>
/// Tells <see cref="VirtualControllerOptions.ConnectionSeen"/> of each host that connects to a controller's port and of its leaving
/// (once each), naming the port and the host as it connected: when it has left, its socket no longer knows its address.
/// </summary>
internal sealed class ConnectionLog(Action<string, string, bool>? seen)
{
    private readonly Lock _gate = new();
    private readonly Dictionary<object, (string Port, string Who)> _open = new(ReferenceEqualityComparer.Instance);

    /// <summary>Tells that the host on <paramref name="connection"/> (known as <paramref name="key"/>) connected to the port named <paramref name="port"/>.</summary>
    public void Connected(string port, object key, Socket connection)
    {
        if (seen is null)
        {
            return;
        }
        string who;
        try
        {
            who = connection.RemoteEndPoint?.ToString() ?? "a host";
        }
        catch (Exception e) when (e is SocketException or ObjectDisposedException)
        {
            who = "a host";
        }
        lock (_gate)
        {
            if (!_open.TryAdd(key, (port, who)))
            {
                return;
            }
        }
        seen(port, who, true);
    }

    /// <summary>Tells that the host known as <paramref name="key"/> left (once, and only after <see cref="Connected"/>).</summary>
    public void Left(object key)
    {
        if (seen is null)
        {
            return;
        }
        (string Port, string Who) open;
        lock (_gate)
        {
            if (!_open.Remove(key, out open))
            {
                return;
            }
        }
        seen(open.Port, open.Who, false);
    }
}
