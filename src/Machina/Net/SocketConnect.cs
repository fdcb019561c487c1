using System.Net;
using System.Net.Sockets;

namespace Machina;

/// <summary>
/// Opens a TCP connection without the runtime's socket engine: a non-blocking <c>connect</c> and <c>poll</c> until it is
/// done. A socket that ever had an asynchronous operation (<see cref="Socket.ConnectAsync(string, int, CancellationToken)"/>
/// among them) stays registered with the engine's <c>epoll</c> for good, and then every arrival on it wakes the engine's
/// thread and queues a thread-pool work item, even while nothing waits for it asynchronously: per streamed action that cost
/// more processor time than the read itself (issue 45). The connections of the links and of the twins' programs are read
/// with <c>poll</c> and non-blocking receives, so they never need the engine. On Linux a peer that answers at once is
/// connected by one blocking <c>connect</c> bounded by the socket's send timeout (no thread, no exception); the socket
/// returned is non-blocking, with Nagle's algorithm off.
/// </summary>
internal static class SocketConnect
{
    /// <summary>How long one <c>poll</c> waits before it looks at the cancellation again, µs.</summary>
    private const int SliceMicroseconds = 20_000;

    /// <summary>
    /// Connects to <paramref name="host"/> when it is an address (not a name) and the system can finish the connection within
    /// <see cref="AtOnceMilliseconds"/>, on the caller's thread (see <see cref="TryConnectAtOnce(IPAddress, int)"/>); null
    /// otherwise (then <see cref="ConnectAsync"/> waits for it). Throws the <see cref="SocketException"/> of a refusal.
    /// </summary>
    internal static Socket? TryConnectAtOnce(string host, int port) =>
        IPAddress.TryParse(host, out IPAddress? address) ? TryConnectAtOnce(address, port) : null;

    /// <summary>
    /// Connects to <paramref name="host"/> (a name is resolved; its addresses are tried in turn) without blocking the caller:
    /// the addresses are tried, and each connection waited for, on a thread of its own (one per connect, not per message).
    /// An address (not a name) is taken as already tried by <see cref="TryConnectAtOnce(string, int)"/>. Throws the last
    /// address's <see cref="SocketException"/> when none accepts, <see cref="OperationCanceledException"/> when cancelled first.
    /// </summary>
    internal static async Task<Socket> ConnectAsync(string host, int port, CancellationToken cancellationToken)
    {
        bool isAddress = IPAddress.TryParse(host, out IPAddress? address);
        IPAddress[] addresses = isAddress
            ? [address!]
            : await Dns.GetHostAddressesAsync(host, cancellationToken).ConfigureAwait(false);
        return await Task.Factory.StartNew(() => ConnectToAny(addresses, port, cancellationToken, tryAtOnce: !isAddress), cancellationToken,
            TaskCreationOptions.LongRunning, TaskScheduler.Default).ConfigureAwait(false);
    }

    /// <summary>
    /// Connects to <paramref name="host"/> on the caller's thread (a twin's program, which waits for its <c>socket_open</c>):
    /// as <see cref="ConnectAsync"/>, blocking.
    /// </summary>
    internal static Socket Connect(string host, int port, CancellationToken cancellationToken) =>
        ConnectToAny(IPAddress.TryParse(host, out IPAddress? address) ? [address] : Dns.GetHostAddresses(host), port, cancellationToken, tryAtOnce: true);

    /// <summary>How long a connection is waited for on the caller's thread before the wait moves to <c>poll</c>, ms.</summary>
    internal const int AtOnceMilliseconds = 10;

    /// <summary>
    /// Linux: one blocking <c>connect</c> bounded by <c>SO_SNDTIMEO</c> (Linux bounds a blocking connect by the socket's send
    /// timeout), which returns the connected socket (non-blocking, Nagle off, the timeout cleared) or null when the connection
    /// takes longer than <see cref="AtOnceMilliseconds"/> (that socket is closed; the caller starts over with <see cref="Start"/>).
    /// A refusal throws its <see cref="SocketException"/>. Elsewhere (a blocking connect is bounded by the system's own timeout
    /// only) always null. The non-blocking connect that <see cref="Start"/> makes throws a <see cref="SocketException"/> for
    /// its <c>EINPROGRESS</c> every time, with its message formatted and the runtime's exception dispatch run: two per
    /// connection of a streamed program (the driver link and its monitor) before this; none now where the peer answers at once
    /// (a controller on the network, a twin on this computer).
    /// </summary>
    private static Socket? TryConnectAtOnce(IPAddress address, int port)
    {
        if (!OperatingSystem.IsLinux())
        {
            return null;
        }
        var socket = new Socket(SocketType.Stream, ProtocolType.Tcp) { NoDelay = true, SendTimeout = AtOnceMilliseconds };
        try
        {
            socket.Connect(address, port);
            socket.SendTimeout = 0;
            socket.Blocking = false;   // Post never waits; the loops wait in poll
            return socket;
        }
        catch (SocketException e) when (e.SocketErrorCode is SocketError.TimedOut or SocketError.WouldBlock or SocketError.InProgress or SocketError.AlreadyInProgress)
        {
            socket.Dispose();   // still under way: a socket whose blocking connect failed is not used again
            return null;
        }
        catch (SocketException e)
        {
            socket.Dispose();
            // Refused or unreachable: the error alone, as Finish reports it (the runtime's own message adds the end point).
            throw new SocketException((int)e.SocketErrorCode);
        }
        catch
        {
            socket.Dispose();
            throw;
        }
    }

    /// <summary>
    /// Tries each address in turn, waiting on the caller's thread (with <paramref name="tryAtOnce"/>, first as
    /// <see cref="TryConnectAtOnce(IPAddress, int)"/>); throws the last refusal when none accepts.
    /// </summary>
    private static Socket ConnectToAny(IPAddress[] addresses, int port, CancellationToken cancellationToken, bool tryAtOnce)
    {
        SocketException? refused = null;
        foreach (IPAddress a in addresses)
        {
            Socket? socket = null;
            try
            {
                if (tryAtOnce && TryConnectAtOnce(a, port) is Socket connected)
                {
                    return connected;
                }
                Socket started = socket = Start(a, port);
                WaitWritable(started, cancellationToken);
                Finish(started);
                return started;
            }
            catch (SocketException e)
            {
                socket?.Dispose();
                refused = e;
            }
            catch
            {
                socket?.Dispose();
                throw;
            }
        }
        throw refused ?? new SocketException((int)SocketError.HostNotFound);
    }

    /// <summary>A new non-blocking socket (dual-mode where the system has IPv6) whose connection to the address is under way.</summary>
    private static Socket Start(IPAddress address, int port)
    {
        var socket = new Socket(SocketType.Stream, ProtocolType.Tcp) { NoDelay = true, Blocking = false };
        try
        {
            socket.Connect(address, port);
        }
        catch (SocketException e) when (e.SocketErrorCode is SocketError.WouldBlock or SocketError.InProgress or SocketError.AlreadyInProgress)
        {
            // Under way: writable once it is made or failed.
        }
        catch
        {
            socket.Dispose();
            throw;
        }
        return socket;
    }

    /// <summary>
    /// Sleeps in <c>poll</c> until the connection is made or failed; throws when cancelled first. A failed connection makes the
    /// socket writable on Linux and macOS but only sets its error condition on Windows, so both are looked at.
    /// </summary>
    private static void WaitWritable(Socket socket, CancellationToken cancellationToken)
    {
        while (!Done(socket, SliceMicroseconds))
        {
            cancellationToken.ThrowIfCancellationRequested();
        }
        cancellationToken.ThrowIfCancellationRequested();
    }

    /// <summary>True when the connection under way is made or failed, waiting up to <paramref name="microseconds"/> for it.</summary>
    private static bool Done(Socket socket, int microseconds) =>
        socket.Poll(microseconds, SelectMode.SelectWrite) || socket.Poll(0, SelectMode.SelectError);

    /// <summary>Throws the connection's error, if it failed (a refused or unreachable peer).</summary>
    private static void Finish(Socket socket)
    {
        var error = (SocketError)(int)socket.GetSocketOption(SocketOptionLevel.Socket, SocketOptionName.Error)!;
        if (error != SocketError.Success || !socket.Connected)
        {
            throw new SocketException((int)(error == SocketError.Success ? SocketError.NotConnected : error));
        }
    }
}
