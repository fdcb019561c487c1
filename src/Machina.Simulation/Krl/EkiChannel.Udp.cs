using System.Net;
using System.Net.Sockets;
using System.Runtime.InteropServices;
using System.Text;

namespace Machina.Simulation.Krl;

/// <summary>
/// EthernetKRL over UDP (PROTOCOL UDP): each datagram is one XML document. As server (TYPE Client) the robot binds its port and
/// answers whoever sent the last datagram; the channel counts as connected (its ALIVE flag up) from the first datagram. As client
/// (TYPE Server) it sends to the configured IP and PORT and counts as connected from EKI_Open. A memory at its limit drops the
/// datagram's further values (UDP has no connection to close) and says so in the logbook.
/// </summary>
internal sealed partial class EkiChannel
{
    private UdpClient? _udp;
    private IPEndPoint? _udpPeer;

    /// <summary>EKI_Open of a UDP channel: binds <paramref name="address"/>:<paramref name="port"/> (server) or any port (client); returns the port bound.</summary>
    private int OpenUdp(IPAddress address, int port)
    {
        UdpClient udp;
        CancellationToken stop;
        bool client = !Configuration.RobotIsServer;
        lock (_gate)
        {
            if (_udp is not null)
            {
                throw new KrlRuntimeException($"EthernetKRL: the channel {Name} is already open");
            }
            if (client && !IPAddress.TryParse(Configuration.Address, out _))
            {
                throw new KrlRuntimeException($"EthernetKRL: the channel {Name} has no server IP address it can send to (\"{Configuration.Address}\")");
            }
            _stop = new CancellationTokenSource();
            stop = _stop.Token;
            udp = new UdpClient(new IPEndPoint(address, client ? 0 : port));
            _udp = udp;
            _udpPeer = client ? new IPEndPoint(IPAddress.Parse(Configuration.Address), port) : null;
        }
        if (client)
        {
            lock (_link)
            {
                Alive(true);
            }
        }
        _ = Task.Run(() => ReceiveDatagramsAsync(udp, stop), CancellationToken.None);
        return client ? port : ((IPEndPoint)udp.Client.LocalEndPoint!).Port;
    }

    private async Task ReceiveDatagramsAsync(UdpClient udp, CancellationToken token)
    {
        while (true)
        {
            UdpReceiveResult datagram;
            try
            {
                datagram = await udp.ReceiveAsync(token).ConfigureAwait(false);
            }
            catch (Exception e) when (e is OperationCanceledException or SocketException or ObjectDisposedException)
            {
                return;
            }
            bool first;
            lock (_gate)
            {
                if (!ReferenceEquals(_udp, udp))
                {
                    return;
                }
                first = _udpPeer is null;
                if (Configuration.RobotIsServer)
                {
                    _udpPeer = datagram.RemoteEndPoint;
                }
            }
            if (first)
            {
                lock (_link)
                {
                    Alive(true);
                }
            }
            var raised = new List<int>();
            EkiXmlSplitter splitter = Splitter((document, memories, flags) => CommitDatagram(udp, document, memories, flags, raised));
            try
            {
                if (Configuration.RawReceive is { } raw)
                {
                    foreach (string record in new EkiRawSplitter(raw).Append(datagram.Buffer))
                    {
                        CommitDatagram(udp, RawDocument(record), null, RawFlags(), raised);
                    }
                    continue;
                }
                splitter.Append(Encoding.UTF8.GetString(datagram.Buffer));
            }
            catch (FormatException ex)
            {
                controller.Pendant.Log($"EthernetKRL {Name}: received a datagram it cannot read ({ex.Message}); it is dropped");
            }
            finally
            {
                RaiseDatagram(udp, raised); // also those of the documents before a malformed part: they were stored
            }
        }
    }

    /// <summary>
    /// Stores a document of a datagram and keeps its flags in <paramref name="raised"/> for the end of the datagram
    /// (<see cref="RaiseDatagram"/>), as a TCP arrival's: a program woken by a flag finds every document of the datagram stored.
    /// </summary>
    private void CommitDatagram(UdpClient udp, List<(string Tag, string Value)> document, List<EkiMemory>? memories, List<int> flags, List<int> raised)
    {
        controller.Options.Seam?.Received(this, CollectionsMarshal.AsSpan(document));
        bool overflow = false;
        lock (_link)
        {
            bool current;
            lock (_gate)
            {
                current = ReferenceEquals(_udp, udp);
            }
            if (current)
            {
                overflow = Store(document, memories, null, dropExcess: true);
                raised.AddRange(flags);
            }
        }
        document.Clear();
        memories?.Clear();
        flags.Clear();
        if (overflow)
        {
            controller.Pendant.Log($"EthernetKRL {Name}: a memory holds {Configuration.Limit} elements (its limit); the datagram's further values are lost");
        }
    }

    /// <summary>
    /// Sets the flags of a datagram's documents once all of them are stored (each flag once), under the link and only while
    /// <paramref name="udp"/> is still the channel's socket, as the store. Before, each document's flags were set as it was
    /// stored, so a program waiting for the first woke while the reader still stored the others and could read a part of it.
    /// </summary>
    private void RaiseDatagram(UdpClient udp, List<int> raised)
    {
        if (raised.Count == 0)
        {
            return;
        }
        lock (_link)
        {
            bool current;
            lock (_gate)
            {
                current = ReferenceEquals(_udp, udp);
            }
            if (current)
            {
                foreach (int flag in raised.Distinct())
                {
                    controller.SetFlag(flag, true);
                }
            }
        }
        raised.Clear();
    }

    /// <summary>Sends one datagram to the peer; false before a peer is known or when the socket is closed.</summary>
    private bool SendDatagram(byte[] bytes)
    {
        UdpClient? udp;
        IPEndPoint? peer;
        lock (_gate)
        {
            udp = _udp;
            peer = _udpPeer;
        }
        if (udp is null || peer is null)
        {
            return false;
        }
        try
        {
            udp.Send(bytes, bytes.Length, peer);
            return true;
        }
        catch (Exception e) when (e is SocketException or ObjectDisposedException)
        {
            return false;
        }
    }

    /// <summary>EKI_Close of a UDP channel: the socket is closed and the ALIVE flag goes down.</summary>
    private void CloseUdp()
    {
        lock (_link)
        {
            UdpClient? udp;
            bool alive;
            lock (_gate)
            {
                udp = _udp;
                alive = _udpPeer is not null;
                _udp = null;
                _udpPeer = null;
                if (udp is not null)
                {
                    _stop?.Cancel();
                }
            }
            udp?.Dispose();
            if (alive)
            {
                Alive(false);
            }
        }
    }
}
