using System.Net.Sockets;
using System.Runtime.CompilerServices;

namespace Machina;

/// <summary>
/// One TCP connection with a receive loop and a send loop. A sender's bytes go straight into the socket when nothing is
/// queued (a non-blocking send); otherwise they wait in an outbox that the send loop writes in one call. Streaming many
/// small requests thus costs no allocation per request and never blocks the caller. What is posted from the receive loop
/// while it hands over a read (the next requests an acknowledgement releases) is held and written in one call when the read
/// is handled, so a block of requests costs one system call, not one each. Disposing cancels both loops and closes the socket.
/// </summary>
internal sealed class TcpLink : IAsyncDisposable
{
    private const int ReceiveBufferSize = 16 * 1024;

    /// <summary>How long the receive loop sleeps in one poll before it looks whether the link is closing, µs.</summary>
    private const int PollMicroseconds = 200_000;

    private readonly Socket _socket;
    private readonly CancellationTokenSource _stop = new();
    private readonly object _outboxGate = new();
    private byte[] _outbox = new byte[4096];
    private int _outboxLength;
    private bool _loopWriting;
    private int _dispatchingThread; // the receive loop's thread while it hands a read to the receiver, else 0
    private int _socketWrites;
    private byte[] _writing = new byte[4096];
    private Task _receiveLoop = Task.CompletedTask;
    private Task _sendLoop = Task.CompletedTask; // started (under the outbox lock) the first time the socket does not take all
    private ILinkReceiver? _receiver;
    private int _disposed;
    private int _socketClosed; // set by the first CloseSocket: the loops leave the socket alone from then on

    private TcpLink(Socket socket, string remoteAddress)
    {
        _socket = socket;
        RemoteAddress = remoteAddress;
    }

    /// <summary>How many times bytes were handed to the socket (direct sends and the send loop's writes), for tests.</summary>
    internal int SocketWrites => Volatile.Read(ref _socketWrites);

    /// <summary>The connection itself (tests look at what watches it).</summary>
    internal Socket Socket => _socket;

    /// <summary>"host:port" of the other end.</summary>
    internal string RemoteAddress { get; }

    /// <summary>The address of this end: the local address that reaches the other end.</summary>
    internal System.Net.IPAddress? LocalAddress => (_socket.LocalEndPoint as System.Net.IPEndPoint)?.Address;

    /// <summary>Wraps a socket that is already connected (e.g. accepted by a server the host opened).</summary>
    internal static TcpLink Adopt(Socket socket, string remoteAddress)
    {
        socket.NoDelay = true;
        socket.Blocking = false; // Post never waits; the loops wait in poll
        return new TcpLink(socket, remoteAddress);
    }

    /// <summary>
    /// Connects within <paramref name="timeout"/>; fails with <see cref="MachinaException"/> when the host cannot be reached. A
    /// peer that answers at once (a controller on the network, a twin on this computer) is connected on the caller's thread
    /// and the task returned is complete: no deadline timer, no thread of its own, no exception (see
    /// <see cref="SocketConnect.TryConnectAtOnce(string, int)"/>).
    /// </summary>
    internal static Task<TcpLink> ConnectAsync(string host, int port, TimeSpan timeout, TimeProvider time, CancellationToken cancellationToken)
    {
        if (cancellationToken.IsCancellationRequested)
        {
            return Task.FromCanceled<TcpLink>(cancellationToken);
        }
        try
        {
            if (SocketConnect.TryConnectAtOnce(host, port) is Socket socket)
            {
                return Task.FromResult(new TcpLink(socket, $"{host}:{port}"));
            }
        }
        catch (SocketException ex)
        {
            return Task.FromException<TcpLink>(Unreachable(host, port, ex));
        }
        return ConnectWaitingAsync(host, port, timeout, time, cancellationToken);
    }

    /// <summary>Connects within <paramref name="timeout"/>, waiting on a thread of <see cref="SocketConnect"/>'s (see <see cref="ConnectAsync"/>).</summary>
    private static async Task<TcpLink> ConnectWaitingAsync(string host, int port, TimeSpan timeout, TimeProvider time, CancellationToken cancellationToken)
    {
        using var deadline = new CancellationTokenSource(timeout, time);
        using var timer = CancellationTokenSource.CreateLinkedTokenSource(cancellationToken, deadline.Token);
        try
        {
            // Non-blocking (Post never waits) and never registered with the runtime's socket engine (see SocketConnect).
            Socket socket = await SocketConnect.ConnectAsync(host, port, timer.Token).ConfigureAwait(false);
            return new TcpLink(socket, $"{host}:{port}");
        }
        catch (OperationCanceledException) when (!cancellationToken.IsCancellationRequested)
        {
            throw new RobotConnectionException($"Could not connect to {host}:{port} within {Num.G(timeout.TotalSeconds)} s; is the driver running there?");
        }
        catch (SocketException ex)
        {
            throw Unreachable(host, port, ex);
        }
    }

    /// <summary>What a refused or unreachable connection fails with.</summary>
    private static RobotConnectionException Unreachable(string host, int port, SocketException ex) =>
        new($"Could not connect to {host}:{port}: {ex.Message}. Is the driver running there?", ex);

    /// <summary>The name of the thread that reads a driver's main link.</summary>
    internal const string ThreadName = "Machina link";

    /// <summary>The name of the thread that reads a side link (a monitor, UR's RTDE or script port): apart in a per-thread reading.</summary>
    internal const string SideThreadName = "Machina side";

    /// <summary>
    /// Starts the receive loop on a thread named <paramref name="threadName"/> (the send loop starts the first time the socket does
    /// not take all that is posted).
    /// </summary>
    internal void Start(ILinkReceiver receiver, string threadName = ThreadName)
    {
        _receiver = receiver;
        var receiving = new TaskCompletionSource(TaskCreationOptions.RunContinuationsAsynchronously);
        _receiveLoop = receiving.Task;
        new Thread(() => ReceiveLoop(receiving)) { IsBackground = true, Name = threadName }.Start();
    }

    /// <summary>
    /// Sends bytes without ever blocking: when nothing is queued they go straight to the socket's buffer (a non-blocking
    /// send), otherwise, or for what did not fit, they are copied to the outbox for the send loop.
    /// </summary>
    internal void Post(ReadOnlySpan<byte> bytes)
    {
        lock (_outboxGate)
        {
            if (_dispatchingThread == Environment.CurrentManagedThreadId)
            {
                Append(bytes); // written by FlushHeld when the read is handled
                return;
            }
            if (_outboxLength == 0 && CanSendNow)
            {
                int sent = SendNow(bytes);
                if (sent < 0)
                {
                    return;
                }
                bytes = bytes[sent..];
                if (bytes.IsEmpty)
                {
                    return;
                }
                // Not all sent (buffer full or an error): the send loop writes the rest or meets and reports the failure.
            }
            Append(bytes);
            RingSendLoop();
        }
    }

    /// <summary>True when bytes may go straight into the socket (under the outbox lock): the send loop is not writing and the link is open.</summary>
    private bool CanSendNow => !_loopWriting && Volatile.Read(ref _disposed) == 0;

    /// <summary>
    /// One non-blocking send (under the outbox lock): how many bytes the socket took, 0 when none (its buffer is full, or an
    /// error the send loop will meet and report), -1 when the link is closing (the bytes are dropped with it).
    /// </summary>
    private int SendNow(ReadOnlySpan<byte> bytes)
    {
        try
        {
            Interlocked.Increment(ref _socketWrites);
            int sent = _socket.Send(bytes, SocketFlags.None, out SocketError error);
            return error is SocketError.Success or SocketError.WouldBlock && sent > 0 ? sent : 0;
        }
        catch (ObjectDisposedException)
        {
            return -1;
        }
    }

    private void Append(ReadOnlySpan<byte> bytes)
    {
        if (_outboxLength + bytes.Length > _outbox.Length)
        {
            Array.Resize(ref _outbox, Math.Max(_outbox.Length * 2, _outboxLength + bytes.Length));
        }
        bytes.CopyTo(_outbox.AsSpan(_outboxLength));
        _outboxLength += bytes.Length;
    }

    /// <summary>Writes what was posted while a read was handed over: straight into the socket when it fits, else by the send loop.</summary>
    private void FlushHeld()
    {
        lock (_outboxGate)
        {
            _dispatchingThread = 0;
            if (_outboxLength == 0)
            {
                return;
            }
            if (CanSendNow)
            {
                int sent = SendNow(_outbox.AsSpan(0, _outboxLength));
                if (sent < 0)
                {
                    _outboxLength = 0;
                    return;
                }
                _outbox.AsSpan(sent, _outboxLength - sent).CopyTo(_outbox);
                _outboxLength -= sent;
                if (_outboxLength == 0)
                {
                    return;
                }
            }
            RingSendLoop();
        }
    }

    /// <summary>
    /// Wakes the send loop for what waits in the outbox (under the outbox lock), starting its thread the first time: most links
    /// never need it, their socket takes every write at once.
    /// </summary>
    private void RingSendLoop()
    {
        if (_sendLoop == Task.CompletedTask)
        {
            if (Volatile.Read(ref _disposed) != 0)
            {
                return;
            }
            var sending = new TaskCompletionSource(TaskCreationOptions.RunContinuationsAsynchronously);
            _sendLoop = sending.Task;
            new Thread(() => SendLoop(sending)) { IsBackground = true, Name = "Machina send" }.Start();
        }
        Monitor.Pulse(_outboxGate);
    }

    /// <summary>
    /// The send loop, on a thread of its own: it sleeps on the outbox until bytes wait there, then writes them with non-blocking
    /// sends, sleeping in <c>poll</c> while the socket's buffer is full. An asynchronous send would register the socket with the
    /// runtime's socket engine for good (see <see cref="SocketConnect"/>), and every later acknowledgement would wake it.
    /// </summary>
    // Optimized at its first call: it runs once per connection, so it would run as first compiled until replaced in the running loop (OSR), compiled inside a stream (perf53e).
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    private void SendLoop(TaskCompletionSource done)
    {
        CancellationToken stop = _stop.Token;
        try
        {
            while (true)
            {
                int length;
                lock (_outboxGate)
                {
                    _loopWriting = false;
                    while (_outboxLength == 0 && !stop.IsCancellationRequested)
                    {
                        Monitor.Wait(_outboxGate, PollMicroseconds / 1000);
                    }
                    if (stop.IsCancellationRequested)
                    {
                        return;
                    }
                    (_outbox, _writing) = (_writing, _outbox);
                    length = _outboxLength;
                    _outboxLength = 0;
                    _loopWriting = true;
                }
                Interlocked.Increment(ref _socketWrites);
                if (!WriteAll(length, stop))
                {
                    return;
                }
            }
        }
        catch (Exception ex) when (ex is SocketException or ObjectDisposedException)
        {
            if (!stop.IsCancellationRequested)
            {
                Closed(ex);
            }
        }
        finally
        {
            done.TrySetResult();
        }
    }

    /// <summary>Writes the first <paramref name="length"/> bytes being written, waiting in <c>poll</c> while the socket takes none; false when the link closes first.</summary>
    private bool WriteAll(int length, CancellationToken stop)
    {
        int offset = 0;
        while (offset < length)
        {
            int sent = _socket.Send(_writing, offset, length - offset, SocketFlags.None, out SocketError error);
            if (error == SocketError.WouldBlock)
            {
                while (!_socket.Poll(PollMicroseconds, SelectMode.SelectWrite))
                {
                    if (stop.IsCancellationRequested)
                    {
                        return false;
                    }
                }
                continue;
            }
            if (error != SocketError.Success)
            {
                throw new SocketException((int)error);
            }
            offset += sent;
        }
        return true;
    }

    /// <summary>
    /// The receive loop, on a thread of its own: it sleeps in <c>poll</c> until bytes arrive and reads them with a non-blocking
    /// receive, so an acknowledgement costs two system calls on one thread. An asynchronous receive cost the socket engine's
    /// <c>epoll_wait</c>, a hand-off to a thread-pool worker and the worker's spinning once idle, for every read.
    /// </summary>
    // Optimized at its first call: it runs once per connection, so it would run as first compiled until replaced in the running loop (OSR), compiled inside a stream (perf53e).
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    private void ReceiveLoop(TaskCompletionSource done)
    {
        CancellationToken stop = _stop.Token;
        byte[] buffer = new byte[ReceiveBufferSize];
        try
        {
            while (!stop.IsCancellationRequested)
            {
                // Bounded, so a closing link is noticed even if closing the socket does not end the wait.
                bool readable = Volatile.Read(ref _socketClosed) == 0 && _socket.Poll(PollMicroseconds, SelectMode.SelectRead);
                if (Volatile.Read(ref _socketClosed) != 0)
                {
                    // Closed here (CloseSocket wakes the poll): reported as a call on the disposed socket would have reported
                    // it, without throwing its ObjectDisposedException on every disconnect.
                    if (!stop.IsCancellationRequested)
                    {
                        Closed(new ObjectDisposedException(typeof(Socket).FullName));
                    }
                    return;
                }
                if (!readable)
                {
                    continue;
                }
                int n = _socket.Receive(buffer, 0, buffer.Length, SocketFlags.None, out SocketError error);
                if (error == SocketError.WouldBlock)
                {
                    continue;
                }
                if (stop.IsCancellationRequested)
                {
                    return;
                }
                if (error != SocketError.Success)
                {
                    Closed(new SocketException((int)error));
                    return;
                }
                if (n == 0)
                {
                    Closed(null);
                    return;
                }
                lock (_outboxGate)
                {
                    _dispatchingThread = Environment.CurrentManagedThreadId;
                }
                try
                {
                    _receiver!.OnReceived(buffer.AsSpan(0, n));
                }
                finally
                {
                    FlushHeld();
                }
            }
        }
        catch (Exception ex)
        {
            // A socket failure, or the handler's own (a codec's bug): on this thread of its own an exception left unhandled
            // would end the process, so the link ends instead and its receiver hears why.
            if (!stop.IsCancellationRequested)
            {
                Closed(ex);
            }
        }
        finally
        {
            done.TrySetResult();
        }
    }

    private void Closed(Exception? error)
    {
        if (Volatile.Read(ref _disposed) == 0)
        {
            _receiver?.OnClosed(error);
        }
    }

    /// <summary>
    /// Closes the socket at once (the peer sees the link end); <see cref="DisposeAsync"/> still stops the loops. Only the first
    /// call does it: a driver closes its links' sockets before it disposes them, and a shutdown of the disposed socket threw.
    /// </summary>
    internal void CloseSocket()
    {
        if (Interlocked.Exchange(ref _socketClosed, 1) != 0)
        {
            return;
        }
        try
        {
            _socket.Shutdown(SocketShutdown.Both);
        }
        catch (Exception e) when (e is SocketException or ObjectDisposedException)
        {
        }
        _socket.Dispose();
    }

    /// <summary>Stops both loops and closes the socket; pending outgoing bytes are dropped.</summary>
    public async ValueTask DisposeAsync()
    {
        if (Interlocked.Exchange(ref _disposed, 1) != 0)
        {
            return;
        }
        await _stop.CancelAsync().ConfigureAwait(false);
        Task sendLoop;
        lock (_outboxGate)
        {
            sendLoop = _sendLoop;
            Monitor.Pulse(_outboxGate);
        }
        CloseSocket();
        try
        {
            await Task.WhenAll(_receiveLoop, sendLoop).ConfigureAwait(false);
        }
        catch (Exception)
        {
            // The loops report their own failures; closing must not throw.
        }
        _stop.Dispose();
    }
}
