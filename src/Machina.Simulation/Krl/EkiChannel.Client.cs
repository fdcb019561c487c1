using System.Net.Sockets;
using Machina.Simulation.Twin;

namespace Machina.Simulation.Krl;

/// <summary>
/// A TCP channel with the robot as client (<c>&lt;EXTERNAL&gt;&lt;TYPE&gt;Server&lt;/TYPE&gt;</c>: the external system is the server):
/// EKI_Open connects to the configured IP and PORT and returns once connected, the ALIVE flag up; the connection is then read and
/// written as a server channel's. A server that does not answer within the connect timeout stops the program with the reason.
/// </summary>
internal sealed partial class EkiChannel
{
    /// <summary>How long EKI_Open waits for the external server to accept.</summary>
    public static readonly TimeSpan ConnectTimeout = TimeSpan.FromSeconds(5);

    /// <summary>Connects to the external server; returns its port.</summary>
    private int Connect()
    {
        CancellationToken stop;
        lock (_gate)
        {
            if (_client is not null)
            {
                throw new KrlRuntimeException($"EthernetKRL: the channel {Name} is already open");
            }
            _stop?.Dispose();
            _stop = new CancellationTokenSource();
            stop = _stop.Token;
        }
        var client = new TcpClient { NoDelay = true };
        try
        {
            using var timeout = CancellationTokenSource.CreateLinkedTokenSource(stop);
            timeout.CancelAfter(ConnectTimeout);
            TwinWait.For(client.ConnectAsync(Configuration.Address, Configuration.Port, timeout.Token).AsTask(), timeout.Token);
        }
        catch (Exception e) when (e is SocketException or OperationCanceledException or ArgumentException)
        {
            client.Dispose();
            string why = e is OperationCanceledException ? $"no answer within {ConnectTimeout.TotalSeconds:0} s" : e.Message;
            throw new KrlRuntimeException($"EthernetKRL: the channel {Name} cannot connect to the server {Configuration.Address}:{Configuration.Port} ({why})");
        }
        _ = Attach(null, client, stop);
        return Configuration.Port;
    }
}
