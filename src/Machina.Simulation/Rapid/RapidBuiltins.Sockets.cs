using System.Net;
using System.Net.Sockets;
using System.Text;
using Machina.Simulation.Twin;

namespace Machina.Simulation.Rapid;

/// <summary>
/// Socket Messaging (SocketCreate, SocketBind, SocketListen, SocketAccept, SocketReceive, SocketSend, SocketClose, SocketGetStatus)
/// on the controller's own TCP sockets, and the interrupt instructions the monitor uses (IDelete, IError, GetTrapData, ReadErrData).
/// A call that waits longer than its <c>\Time</c> raises ERR_SOCK_TIMEOUT; a connection closed by the other end raises ERR_SOCK_CLOSED.
/// </summary>
internal static partial class RapidBuiltins
{
    private const double DefaultSocketSeconds = 60;

    private static IEnumerable<RapidBuiltin> Sockets() =>
    [
        Instruction("SocketCreate", [P("Socket", "socketdev"), Sw("UDP")], call =>
        {
            RapidSocketDevice s = Device(call);
            if (s.Status != 0)
            {
                throw call.Error(RapidErrorNumbers.SockAddrInUse, "SocketCreate: the socket is already created");
            }
            if (call.Has(1))
            {
                s.Udp = new Socket(AddressFamily.InterNetwork, SocketType.Dgram, ProtocolType.Udp);
            }
            s.Status = 1;
            call.Machine.Task.Controller.Track(s);
        }),
        Instruction("SocketBind", [P("Socket", "socketdev"), P("LocalAddress", "string"), P("LocalPort", "num")], call =>
        {
            RapidSocketDevice s = Device(call);
            if (!IPAddress.TryParse(call.Str(1), out IPAddress? address))
            {
                throw ArgumentError(call, $"SocketBind: \"{call.Str(1)}\" is not an IP address");
            }
            s.Bound = new IPEndPoint(call.Machine.Task.Controller.BindAddress(address), (int)call.Num(2));
            try
            {
                s.Udp?.Bind(s.Bound);
            }
            catch (SocketException ex)
            {
                throw call.Error(RapidErrorNumbers.SockAddrInUse, $"SocketBind: {ex.Message}");
            }
            s.Status = 3;
        }),
        Instruction("SocketListen", [P("Socket", "socketdev")], call =>
        {
            RapidSocketDevice s = Device(call);
            if (s.Bound is null)
            {
                throw ArgumentError(call, "SocketListen: the socket is not bound");
            }
            try
            {
                s.Listener = call.Machine.Task.Controller.TakeReserved(s.Bound) ?? new TcpListener(s.Bound);
                s.Listener.Start(1);
            }
            catch (SocketException ex)
            {
                throw call.Error(RapidErrorNumbers.SockAddrInUse, $"SocketListen: {ex.Message}");
            }
            s.Status = 4;
        }),
        Instruction("SocketAccept", [P("Socket", "socketdev"), P("ClientSocket", "socketdev"), Opt("ClientAddress", "string", true), Opt("Time", "num")], call =>
        {
            RapidSocketDevice server = Device(call);
            var client = (RapidSocketDevice)call.Value(1);
            TcpListener listener = server.Listener ?? throw ArgumentError(call, "SocketAccept: the socket is not listening");
            IRapidSocketSeam? seam = call.Machine.Task.Controller.Options.Seam;
            Socket accepted;
            TwinHeldOutbox outbox;
            do
            {
                using var abandon = CancellationTokenSource.CreateLinkedTokenSource(call.Machine.Task.CancellationToken);
                Task<Socket> accept = listener.AcceptSocketAsync(abandon.Token).AsTask();
                if (!WaitForAccept(call, accept, abandon, call.Has(3) ? call.Num(3) : DefaultSocketSeconds))
                {
                    throw call.Error(RapidErrorNumbers.SockTimeout, "SocketAccept: no client connected in time");
                }
                if (accept.IsFaulted)
                {
                    throw call.Error(RapidErrorNumbers.SockClosed, "SocketAccept: the socket was closed");
                }
                accepted = accept.Result;
                if (call.Machine.Task.CancellationToken.IsCancellationRequested)
                {
                    // Accepted as the task was stopped: the stopped program serves no one, the client sees the link close.
                    accepted.Dispose();
                    throw new OperationCanceledException("SocketAccept: the task was stopped.");
                }
                call.Machine.Task.Sends.Own(); // this task's thread: what it writes on the connection is held until it waits
                outbox = new TwinHeldOutbox(accepted, call.Machine.Task.Sends);
            }
            while (seam is not null && !seam.Accepted(((IPEndPoint)listener.LocalEndpoint).Port, accepted, outbox, call.Machine.Task.CancellationToken));
            client.Connection = accepted;
            client.Outbox = outbox;
            client.Connection.NoDelay = true;
            if (call.Has(2))
            {
                call.Set(2, (accepted.RemoteEndPoint as IPEndPoint)?.Address.ToString() ?? "");
            }
            client.Status = 2;
        }),
        // The bytes go to the connection's outbox, which the network stack writes when the task next waits (TwinHeldOutbox): a write
        // that failed there raises ERR_SOCK_CLOSED at the task's next SocketSend on the connection.
        Instruction("SocketSend", [P("Socket", "socketdev"), Opt("Str", "string"), Opt("RawData", "rawbytes"), Opt("Data", null), Opt("NoOfBytes", "num")], call =>
        {
            Socket connection = Connected(call);
            TwinHeldOutbox outbox = Device(call).Outbox!;
            byte[] bytes = SendBytes(call);
            try
            {
                // A send that failed raises the RAPID error with the text it always had, without a .NET exception before it.
                if (call.Machine.Task.Controller.Options.Seam is { } seam)
                {
                    if (!seam.Send(connection, outbox, bytes, call.Machine.Task.CancellationToken))
                    {
                        throw call.Error(RapidErrorNumbers.SockClosed, $"SocketSend: {new SocketException((int)SocketError.ConnectionReset).Message}");
                    }
                }
                else if (!outbox.TryWrite(bytes))
                {
                    throw call.Error(RapidErrorNumbers.SockClosed, "SocketSend: The connection is closed.");
                }
            }
            catch (Exception ex) when (ex is SocketException or ObjectDisposedException or IOException)
            {
                throw call.Error(RapidErrorNumbers.SockClosed, $"SocketSend: {ex.Message}");
            }
        }),
        Instruction("SocketReceive", [P("Socket", "socketdev"), Opt("Str", "string", true), Opt("RawData", "rawbytes", true), Opt("Data", null, true),
            Opt("ReadNoOfBytes", "num"), Opt("NoRecBytes", "num", true), Opt("Time", "num")], call =>
        {
            Socket connection = Connected(call);
            double seconds = call.Has(6) ? call.Num(6) : DefaultSocketSeconds;
            if (!call.Has(1))
            {
                ReceiveRaw(call, connection, seconds);
                return;
            }
            int wanted = call.Has(4) ? (int)call.Num(4) : 0;
            if ((call.Has(4) && wanted < 1) || wanted > RapidMachine.MaxStringLength)
            {
                throw ArgumentError(call, $"SocketReceive: \\ReadNoOfBytes {wanted} is outside 1..{RapidMachine.MaxStringLength} for \\Str");
            }
            // \ReadNoOfBytes is how many bytes to take at most: the receive returns what has arrived, as programs written for
            // controllers read it (they ask 1024 and read \NoRecBytes; docs/simulation.md, session 33).
            string text = ReceiveText(call, connection, wanted > 0 ? wanted : RapidMachine.MaxStringLength, seconds);
            call.Set(1, text);
            if (call.Has(5))
            {
                call.Set(5, (double)text.Length);
            }
        }),
        Instruction("SocketClose", [P("Socket", "socketdev")], call =>
        {
            RapidSocketDevice s = Device(call);
            s.Outbox?.Flush(); // what the task sent goes out before the close
            try
            {
                // A graceful close (FIN), also while the controller's network stack still waits for data on it (a socket disposed
                // with a receive pending would be reset).
                s.Connection?.Shutdown(SocketShutdown.Both);
            }
            catch (Exception e) when (e is SocketException or ObjectDisposedException)
            {
                // Already closed or reset by the other end.
            }
            s.Connection?.Dispose();
            s.Listener?.Stop();
            s.Udp?.Dispose();
            (s.Connection, s.Outbox, s.Listener, s.Udp, s.Bound, s.Status, s.PendingDatagram) = (null, null, null, null, null, 0, null);
        }),
        Function("SocketPeek", "num", [P("Socket", "socketdev")], call =>
        {
            Socket connection = Connected(call);
            try
            {
                return (double)(connection.Available + Device(call).Held(connection).Count);
            }
            catch (Exception ex) when (ex is ObjectDisposedException or SocketException)
            {
                throw call.Error(RapidErrorNumbers.SockClosed, "SocketPeek: the connection is closed");
            }
        }),
        Function("SocketGetStatus", "socketstatus", [P("Socket", "socketdev")], call => (double)(Device(call).Status == 0 ? 5 : Device(call).Status)),
    ];

    private static IEnumerable<RapidBuiltin> Interrupts() =>
    [
        Instruction("IDelete", [P("Interrupt", "intnum")], call => call.Machine.Task.DeleteInterrupt((int)call.Num(0))),
        Instruction("IError", [P("ErrorDomain", "num"), Opt("ErrorId", "num"), P("ErrorType", "num"), P("Interrupt", "intnum")], call =>
        {
            int number = call.Has(1) ? (int)call.Num(1) : -1;
            if (!call.Machine.Task.OrderErrorInterrupt((int)call.Num(3), (int)call.Num(0), number, (int)call.Num(2)))
            {
                throw call.Error(RapidErrorNumbers.ArgValErr, "IError: the interrupt is not connected to a trap (CONNECT it first)");
            }
        }),
        Instruction("IPers", [P("Name", null, true), P("Interrupt", "intnum")], call =>
        {
            RapidCall order = call;
            if (!call.Machine.Task.OrderPersInterrupt((int)call.Num(1), () => order.Value(0), call.DataCell(0)))
            {
                throw call.Error(RapidErrorNumbers.ArgValErr, "IPers: the interrupt is not connected to a trap (CONNECT it first)");
            }
        }),
        Instruction("GetTrapData", [P("TrapEvent", "trapdata", true)], call =>
        {
            RapidTrapData data = call.Machine.Task.CurrentTrapData
                ?? throw call.Error(RapidErrorNumbers.ArgValErr, "GetTrapData is used outside a trap routine");
            call.Set(0, new RapidTrapData { Domain = data.Domain, Number = data.Number, Kind = data.Kind });
        }),
        Instruction("ReadErrData", [P("TrapEvent", "trapdata"), P("ErrorDomain", "errdomain", true), P("ErrorId", "num", true), P("ErrorType", "errtype", true)], call =>
        {
            var data = (RapidTrapData)call.Value(0);
            call.Set(1, data.Domain);
            call.Set(2, data.Number);
            call.Set(3, data.Kind);
        }),
    ];

    /// <summary>
    /// Reads what already arrived without waiting (no task for the common case of a host streaming ahead): the count, 0 when the
    /// connection is closed, or -1 when nothing is there yet (the caller waits for it).
    /// </summary>
    private static int ReceiveReady(Socket connection, byte[] buffer)
    {
        try
        {
            return connection.Available > 0 ? connection.Receive(buffer, SocketFlags.None) : -1;
        }
        catch (ObjectDisposedException)
        {
            return 0;
        }
        catch (SocketException)
        {
            return 0;
        }
    }

    private static RapidSocketDevice Device(RapidCall call) => (RapidSocketDevice)call.Value(0);

    private static Socket Connected(RapidCall call) => Device(call).Connection
        ?? throw call.Error(RapidErrorNumbers.SockClosed, "the socket is not connected");

    /// <summary>Waits for a socket operation up to <paramref name="seconds"/>; false when it timed out.</summary>
    private static bool Wait(RapidCall call, Task operation, double seconds)
    {
        CancellationToken cancellation = call.Machine.Task.CancellationToken;
        Twin.TwinWait.For(operation, TimeSpan.FromSeconds(Math.Min(seconds, 86_400)), cancellation);
        // A controller that stops its tasks cancels them, then closes their sockets: an operation that failed because its
        // socket closed under a stopping task was stopped, not a program error (the restart logged "socket was closed" at times).
        if (operation.IsCanceled || (operation.IsFaulted && cancellation.IsCancellationRequested))
        {
            throw new OperationCanceledException("The socket operation was cancelled.");
        }
        return operation.IsCompleted;
    }
}
