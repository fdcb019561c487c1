using System.Net.Sockets;
using System.Text;

namespace Machina.Simulation.Rapid;

/// <summary>
/// SocketReceive's wait for bytes (\Str, \RawData and \Data alike): what the controller's network stack holds for the connection,
/// taken once at least one byte is there, at most the data type's size or \ReadNoOfBytes; a timeout with nothing arrived takes
/// nothing, and a receive it started is kept for the next SocketReceive.
/// </summary>
internal static partial class RapidBuiltins
{
    /// <summary>
    /// What has arrived, at most <paramref name="max"/> bytes (one character each), waiting until at least one byte is there;
    /// ERR_SOCK_TIMEOUT when <paramref name="seconds"/> run out first, ERR_SOCK_CLOSED when the connection closed before.
    /// </summary>
    private static string ReceiveText(RapidCall call, Socket connection, int max, double seconds)
    {
        IRapidSocketSeam? seam = call.Machine.Task.Controller.Options.Seam;
        long deadline = Environment.TickCount64 + (long)(Math.Min(seconds, 86_400) * 1000);
        string? taken;
        if (seam?.Inbox(connection) is { } inbox)
        {
            // The controller read the socket already: take what it holds, as from a network stack's buffer.
            while ((taken = inbox.TryTake(max, out Task arrival)) is null)
            {
                if (!Wait(call, arrival, Remaining(deadline)))
                {
                    throw ReceiveTimeout(call);
                }
            }
        }
        else
        {
            RapidInbox held = Device(call).Held(connection);
            ReadArrived(call, connection, held);
            while ((taken = held.TryTake(max, out _)) is null)
            {
                ReadSocket(call, connection, held, max, deadline);
            }
        }
        if (taken.Length == 0)
        {
            seam?.Closed(connection, call.Machine.Task.CancellationToken);
            Device(call).Status = 5;
            throw call.Error(RapidErrorNumbers.SockClosed, "SocketReceive: the connection is closed");
        }
        return taken;
    }

    /// <summary>
    /// Reads what arrives next on <paramref name="connection"/> into <paramref name="held"/> (closing it when the other end
    /// closed); ERR_SOCK_TIMEOUT at <paramref name="deadline"/>, the started receive kept for the next SocketReceive.
    /// </summary>
    private static void ReadSocket(RapidCall call, Socket connection, RapidInbox held, int size, long deadline)
    {
        RapidSocketDevice device = Device(call);
        var buffer = new byte[size];
        int count = device.PendingReceive is null ? ReceiveReady(connection, buffer) : -1;
        if (count < 0)
        {
            if (device.PendingReceive is not { } pending)
            {
                Task<int> receive;
                try
                {
                    receive = connection.ReceiveAsync(buffer, SocketFlags.None, call.Machine.Task.CancellationToken).AsTask();
                }
                catch (ObjectDisposedException)
                {
                    receive = Task.FromResult(0); // closed by the controller (a fault a test injected): as closed by the other end
                }
                pending = (receive, buffer);
                device.PendingReceive = pending;
            }
            if (!Wait(call, pending.Receive, Remaining(deadline)))
            {
                throw ReceiveTimeout(call);
            }
            device.PendingReceive = null;
            (count, buffer) = (pending.Receive.IsFaulted ? 0 : pending.Receive.Result, pending.Buffer);
        }
        Deliver(call, connection, held, count, buffer);
    }

    /// <summary>
    /// Moves into <paramref name="held"/> what arrived and waits in the socket (and what a receive that a timed-out SocketReceive
    /// started got), without waiting: as in a network stack's buffer, a receive then sees everything that arrived.
    /// </summary>
    private static void ReadArrived(RapidCall call, Socket connection, RapidInbox held)
    {
        RapidSocketDevice device = Device(call);
        if (device.PendingReceive is { Receive.IsCompleted: true } done)
        {
            device.PendingReceive = null;
            Deliver(call, connection, held, done.Receive.IsFaulted ? 0 : done.Receive.Result, done.Buffer);
        }
        if (device.PendingReceive is not null)
        {
            return;
        }
        byte[]? buffer = null;
        int count;
        while ((count = ReceiveReady(connection, buffer ??= new byte[RapidRawBytes.Capacity])) > 0)
        {
            Deliver(call, connection, held, count, buffer);
        }
        if (count == 0)
        {
            held.Close();
        }
    }

    private static void Deliver(RapidCall call, Socket connection, RapidInbox held, int count, byte[] buffer)
    {
        if (count == 0)
        {
            held.Close();
            return;
        }
        string text = Encoding.Latin1.GetString(buffer, 0, count);
        call.Machine.Task.Controller.Options.Seam?.Received(connection, text, call.Machine.Task.CancellationToken);
        held.Add(text);
    }

    private static double Remaining(long deadline) => Math.Max(0, deadline - Environment.TickCount64) / 1000.0;

    private static RapidRuntimeException ReceiveTimeout(RapidCall call) => call.Error(RapidErrorNumbers.SockTimeout, "SocketReceive: nothing received in time");
}
