using System.Net.Sockets;
using Machina.Simulation.Twin;

namespace Machina.Simulation.Rapid;

/// <summary>A <c>socketdev</c>: one of the controller's TCP sockets (created, bound, listening or connected), or a UDP socket.</summary>
internal sealed class RapidSocketDevice
{
    /// <summary>The listening socket, when this device listens.</summary>
    public TcpListener? Listener { get; set; }

    /// <summary>The connection, when this device is connected.</summary>
    public Socket? Connection { get; set; }

    /// <summary>What the controller's network stack holds to send on <see cref="Connection"/> (SocketSend writes here), when connected.</summary>
    public TwinHeldOutbox? Outbox { get; set; }

    /// <summary>The state SocketGetStatus reports (SOCKET_CREATED…; 0 before SocketCreate).</summary>
    public int Status { get; set; }

    /// <summary>The datagram socket of a socket created with \UDP (SocketSendTo, SocketReceiveFrom), or null.</summary>
    public Socket? Udp { get; set; }

    /// <summary>A UDP receive that a SocketReceiveFrom started and that timed out, with its buffer: the next one takes its datagram.</summary>
    public (Task<SocketReceiveFromResult> Receive, byte[] Buffer)? PendingDatagram { get; set; }

    /// <summary>The address given to SocketBind.</summary>
    public System.Net.IPEndPoint? Bound { get; set; }
}
