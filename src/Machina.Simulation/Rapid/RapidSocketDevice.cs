using System.Net.Sockets;

namespace Machina.Simulation.Rapid;

/// <summary>A <c>socketdev</c>: one of the controller's TCP sockets (created, bound, listening or connected).</summary>
internal sealed class RapidSocketDevice
{
    /// <summary>The listening socket, when this device listens.</summary>
    public TcpListener? Listener { get; set; }

    /// <summary>The connection, when this device is connected.</summary>
    public Socket? Connection { get; set; }

    /// <summary>The state SocketGetStatus reports (SOCKET_CREATED…; 0 before SocketCreate).</summary>
    public int Status { get; set; }

    /// <summary>The address given to SocketBind.</summary>
    public System.Net.IPEndPoint? Bound { get; set; }
}
