using System.Net.Sockets;
using Machina.Simulation.Twin;

namespace Machina.Simulation.Rws;

internal sealed partial class RwsTwinServer
{
    /// <summary>
    /// The most connections the server serves at once; a client past it is answered 503 and closed (docs/reliability.md,
    /// "Connections per port"). ABB's manual names no number for RWS 1.0; the twin's own, far above what its clients open.
    /// </summary>
    public const int MaxConnections = 64;

    /// <summary>How long the refusal may take to leave before the connection is closed anyway.</summary>
    private static readonly TimeSpan RefusalDeadline = TimeSpan.FromSeconds(1);

    private readonly ConnectionCap _connections = new(MaxConnections);

    /// <summary>Connections refused because <see cref="MaxConnections"/> were open.</summary>
    public int ConnectionsRefused => Volatile.Read(ref _connectionsRefused);

    private int _connectionsRefused;

    /// <summary>Answers a client past the limit 503 Service Unavailable (within <see cref="RefusalDeadline"/>) and closes it.</summary>
    private async Task RefuseAsync(TcpClient client, CancellationToken cancellationToken)
    {
        Interlocked.Increment(ref _connectionsRefused);
        using (client)
        {
            try
            {
                using var deadline = CancellationTokenSource.CreateLinkedTokenSource(cancellationToken);
                deadline.CancelAfter(RefusalDeadline);
                RwsResponse answer = RwsXhtmlWriter.Error(503, "Service Unavailable", null,
                    $"{MaxConnections} connections are open, the most this server serves at once; close one or try again later.");
                answer.Headers.Add(("Connection", "close"));
                await RwsHttp.WriteAsync(client.GetStream(), answer, deadline.Token).ConfigureAwait(false);
            }
            catch (Exception ex) when (ex is IOException or SocketException or ObjectDisposedException or OperationCanceledException)
            {
                // The client left first: closed all the same.
            }
        }
    }
}
