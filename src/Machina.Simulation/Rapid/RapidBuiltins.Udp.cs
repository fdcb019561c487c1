using System.Net;
using System.Net.Sockets;
using System.Text;

namespace Machina.Simulation.Rapid;

/// <summary>
/// UDP sockets (RAPID Socket Messaging: SocketCreate \UDP, SocketBind, SocketSendTo, SocketReceiveFrom): a datagram per call, sent
/// to or received from any address; SocketReceiveFrom needs SocketBind first, tells who sent the datagram, waits up to \Time (60 s)
/// and raises ERR_SOCK_TIMEOUT then. A datagram longer than \Str's 80 characters or 1024 raw bytes keeps only its first ones.
/// </summary>
internal static partial class RapidBuiltins
{
    private static IEnumerable<RapidBuiltin> Udp() =>
    [
        Instruction("SocketSendTo", [P("Socket", "socketdev"), P("RemoteAddress", "string"), P("RemotePort", "num"), Opt("Str", "string"), Opt("RawData", "rawbytes"),
            Opt("Data", null), Opt("NoOfBytes", "num")], call =>
        {
            Socket udp = Datagram(call, "SocketSendTo");
            if (!IPAddress.TryParse(call.Str(1), out IPAddress? address))
            {
                throw ArgumentError(call, $"SocketSendTo: \"{call.Str(1)}\" is not an IP address");
            }
            byte[] bytes = SendBytes(call, 3);
            try
            {
                udp.SendTo(bytes, new IPEndPoint(address, (int)call.Num(2)));
            }
            catch (Exception ex) when (ex is SocketException or ObjectDisposedException)
            {
                throw call.Error(RapidErrorNumbers.SockClosed, $"SocketSendTo: {ex.Message}");
            }
        }),
        Instruction("SocketReceiveFrom", [P("Socket", "socketdev"), Opt("Str", "string", true), Opt("RawData", "rawbytes", true), Opt("Data", null, true),
            Opt("NoRecBytes", "num", true), P("RemoteAddress", "string", true), P("RemotePort", "num", true), Opt("Time", "num")], call =>
        {
            Socket udp = Datagram(call, "SocketReceiveFrom");
            if (Device(call).Bound is null)
            {
                throw ArgumentError(call, "SocketReceiveFrom: the socket is not bound (SocketBind first)");
            }
            RapidSocketDevice device = Device(call);
            (Task<SocketReceiveFromResult> receive, byte[] buffer) = device.PendingDatagram ?? Receive(call, udp);
            device.PendingDatagram = null;
            if (!Wait(call, receive, call.Has(7) ? call.Num(7) : DefaultSocketSeconds))
            {
                device.PendingDatagram = (receive, buffer); // still under way: the next SocketReceiveFrom takes its datagram
                throw call.Error(RapidErrorNumbers.SockTimeout, "SocketReceiveFrom: nothing received in time");
            }
            if (receive.IsFaulted)
            {
                throw call.Error(RapidErrorNumbers.SockClosed, "SocketReceiveFrom: the socket is closed");
            }
            SocketReceiveFromResult result = receive.Result;
            byte[] received = buffer[..result.ReceivedBytes];
            if (call.Has(1))
            {
                string text = Encoding.Latin1.GetString(received, 0, Math.Min(received.Length, RapidMachine.MaxStringLength));
                call.Set(1, text);
                received = Encoding.Latin1.GetBytes(text);
            }
            else if (call.Has(2) || call.Has(3))
            {
                StoreReceived(call, 2, received);
            }
            else
            {
                throw ArgumentError(call, "SocketReceiveFrom needs \\Str, \\RawData or \\Data");
            }
            if (call.Has(4))
            {
                call.Set(4, (double)received.Length);
            }
            var from = (IPEndPoint)result.RemoteEndPoint;
            call.Set(5, from.Address.ToString());
            call.Set(6, (double)from.Port);
        }),
    ];

    private static (Task<SocketReceiveFromResult>, byte[]) Receive(RapidCall call, Socket udp)
    {
        var buffer = new byte[RapidRawBytes.Capacity];
        try
        {
            return (udp.ReceiveFromAsync(buffer, SocketFlags.None, new IPEndPoint(IPAddress.Any, 0), call.Machine.Task.CancellationToken).AsTask(), buffer);
        }
        catch (ObjectDisposedException)
        {
            throw call.Error(RapidErrorNumbers.SockClosed, "SocketReceiveFrom: the socket is closed");
        }
    }

    private static Socket Datagram(RapidCall call, string name) => Device(call).Udp
        ?? throw call.Error(RapidErrorNumbers.SockClosed, $"{name}: the socket is not a UDP socket (SocketCreate \\UDP)");
}
