using System.Net.Sockets;
using Machina.Simulation.Twin;

namespace Machina.Simulation.Rapid;

/// <summary>A <c>socketdev</c>: one of the controller's TCP sockets (created, bound, listening or connected), or a UDP socket.</summary>
internal sealed class RapidSocketDevice
{
    private RapidInbox? _held;
    private Socket? _heldFor;

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

    /// <summary>
    /// What the controller's network stack read from <paramref name="connection"/> and the program has not received yet (a
    /// SocketReceive \ReadNoOfBytes that timed out before its count leaves the bytes here for the next receive); a new
    /// connection starts empty.
    /// </summary>
    public RapidInbox Held(Socket connection)
    {
        if (_held is null || !ReferenceEquals(_heldFor, connection))
        {
            (_held, _heldFor, PendingReceive) = (new RapidInbox(), connection, null);
        }
        return _held;
    }

    /// <summary>A TCP receive that a SocketReceive started and that timed out, with its buffer: the next one takes its bytes.</summary>
    public (Task<int> Receive, byte[] Buffer)? PendingReceive { get; set; }

    /// <summary>The address given to SocketBind.</summary>
    public System.Net.IPEndPoint? Bound { get; set; }
}
