using System.Net.Sockets;

namespace Machina.Simulation.Rapid;

/// <summary>
/// Where a controller that hosts the twin watches and disturbs the program's own sockets, at the points a real controller's
/// network has: a connection accepted, text received, text sent. Without a seam the sockets work directly.
/// </summary>
internal interface IRapidSocketSeam
{
    /// <summary>
    /// A connection was accepted on <paramref name="localPort"/>; false refuses it (it is closed and SocketAccept waits on).
    /// <paramref name="outbox"/> is where the controller writes to it (what the accepting task writes is held until it waits).
    /// </summary>
    bool Accepted(int localPort, Socket connection, Stream outbox, CancellationToken task);

    /// <summary>The program received <paramref name="text"/> on <paramref name="connection"/> (SocketReceive returns it next).</summary>
    void Received(Socket connection, string text, CancellationToken task);

    /// <summary>SocketReceive found <paramref name="connection"/> closed: the program read everything it will read from it.</summary>
    void Closed(Socket connection, CancellationToken task);

    /// <summary>
    /// What the controller already read from <paramref name="connection"/> for the program (SocketReceive takes from it, and
    /// <see cref="Received"/> is not called), or null when the program reads the socket itself.
    /// </summary>
    RapidInbox? Inbox(Socket connection);

    /// <summary>
    /// The program sends <paramref name="bytes"/> on <paramref name="connection"/> (each SocketSend); they go out through
    /// <paramref name="outbox"/>. False when the connection is closed (ERR_SOCK_CLOSED).
    /// </summary>
    bool Send(Socket connection, Stream outbox, byte[] bytes, CancellationToken task);
}
