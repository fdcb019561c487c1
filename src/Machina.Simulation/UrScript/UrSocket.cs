using System.Buffers.Binary;
using System.Net.Sockets;
using System.Text;
using Machina.Simulation.Twin;

namespace Machina.Simulation.UrScript;

/// <summary>
/// One client socket a program opened with <c>socket_open</c>. Reads wait up to their timeout for complete values; bytes of a
/// value that has not fully arrived stay for the next read, so nothing half-read is lost.
/// </summary>
internal sealed class UrSocket(Socket socket) : IDisposable
{
    private byte[] _buffer = new byte[64 * 1024];
    private int _start;
    private int _end;
    private bool _closed;

    private int Buffered => _end - _start;

    /// <summary>The connection itself (the virtual UR attaches it as its driver connection).</summary>
    internal Socket Connection => socket;

    /// <summary>Who watches this socket's reads and carries its writes, or null (writes go straight out).</summary>
    internal IUrSocketSeam? Seam { get; set; }

    private bool IsDisposed
    {
        get
        {
            try
            {
                return socket.SafeHandle.IsClosed;
            }
            catch (ObjectDisposedException)
            {
                return true;
            }
        }
    }

    /// <summary>
    /// The controller's network stack for this connection when the virtual UR made it its driver connection, or null (writes go
    /// straight out): what the program's own thread writes is held until it is about to wait (<see cref="TwinHeldOutbox"/>).
    /// </summary>
    internal TwinHeldOutbox? Held { get; set; }

    /// <summary>Cancelled when the program that opened this socket stops (a write the seam holds ends then).</summary>
    internal CancellationToken Program { get; set; }

    private ReadOnlySpan<byte> Pending => _buffer.AsSpan(_start, _end - _start);

    private void Consume(int count) => _start += count;

    /// <summary>Makes room for at least one more chunk at the end of the buffer.</summary>
    private void MakeRoom()
    {
        if (_start > 0)
        {
            Buffer.BlockCopy(_buffer, _start, _buffer, 0, Buffered);
            _end -= _start;
            _start = 0;
        }
        if (_buffer.Length - _end < 16 * 1024)
        {
            Array.Resize(ref _buffer, _buffer.Length * 2);
        }
    }

    /// <summary>Opens a TCP connection, waiting at most <paramref name="timeout"/>; null when it cannot connect.</summary>
    public static UrSocket? Connect(string address, int port, TimeSpan timeout, CancellationToken cancellation)
    {
        try
        {
            using var cts = CancellationTokenSource.CreateLinkedTokenSource(cancellation);
            cts.CancelAfter(timeout);
            // Without the runtime's socket engine: a socket it watches wakes its thread and the thread pool at every arrival,
            // while the program reads with poll (issue 45). Blocking again once connected: the program's writes wait, as on
            // the controller.
            Socket socket = SocketConnect.Connect(address, port, cts.Token);
            socket.Blocking = true;
            return new UrSocket(socket);
        }
        catch (Exception e) when (e is SocketException or OperationCanceledException or ArgumentException)
        {
            // A program stopped while it connects stops (whatever the connect said); otherwise socket_open gives False.
            cancellation.ThrowIfCancellationRequested();
            return null;
        }
    }

    /// <summary>True when something is there to read without waiting.</summary>
    public bool HasData
    {
        get
        {
            try
            {
                return Buffered > 0 || (!IsDisposed && socket.Available > 0);
            }
            catch (Exception e) when (e is ObjectDisposedException or SocketException)
            {
                return false;
            }
        }
    }

    /// <summary>True when the last read's time ran out before its data had all arrived (the connection still open).</summary>
    public bool TimedOut { get; private set; }

    /// <summary>Waits until <paramref name="count"/> bytes are buffered or the time is up; true when they are.</summary>
    private bool Fill(int count, double timeoutSeconds, CancellationToken cancellation)
    {
        if (!_closed && IsDisposed)
        {
            // Closed by the controller (a dropped connection): what was buffered cannot be read any more.
            _closed = true;
            _start = _end = 0;
        }
        // The Script Manual: a timeout of 0 or less never times out (UR's clients make their first read blocking with 0).
        if (Buffered < count && !_closed)
        {
            // About to wait for the host: what this thread sent is held until now (the acknowledgements of the burst it ran).
            TwinWait.Blocking();
        }
        long deadline = timeoutSeconds > 0 ? Environment.TickCount64 + (long)(timeoutSeconds * 1000) : long.MaxValue;
        while (Buffered < count && !_closed)
        {
            cancellation.ThrowIfCancellationRequested();
            long left = deadline - Environment.TickCount64;
            int slice = (int)Math.Clamp(left, 0, 50);
            bool readable;
            try
            {
                readable = socket.Poll(slice * 1000, SelectMode.SelectRead);
            }
            catch (Exception e) when (e is ObjectDisposedException or SocketException)
            {
                _closed = true;
                break;
            }
            if (!readable)
            {
                if (left <= 0)
                {
                    break; // the time is up
                }
                continue;
            }
            int read;
            if (_buffer.Length - _end < 16 * 1024)
            {
                MakeRoom();
            }
            try
            {
                read = socket.Receive(_buffer, _end, _buffer.Length - _end, SocketFlags.None);
            }
            catch (Exception e) when (e is SocketException or ObjectDisposedException)
            {
                read = 0;
            }
            if (read == 0)
            {
                _closed = true;
                break;
            }
            _end += read;
        }
        if (Buffered < count && _closed)
        {
            // A program that reads a closed connection in a loop would spin; on the twin each such read takes its timeout.
            cancellation.WaitHandle.WaitOne(TimeSpan.FromSeconds(Math.Clamp(timeoutSeconds, 0, 1)));
        }
        TimedOut = Buffered < count && !_closed;
        return Buffered >= count;
    }

    /// <summary>
    /// <c>socket_read_binary_integer</c>: [n, v1 … vn] with big-endian signed 32-bit values; [0, -1 …] when they did not all
    /// arrive in time (what did arrive stays buffered).
    /// </summary>
    public UrList ReadIntegers(int count, double timeoutSeconds, CancellationToken cancellation)
    {
        var items = new object[count + 1];
        if (!Fill(4 * count, timeoutSeconds, cancellation))
        {
            items[0] = UrValue.Box(0);
            for (int i = 1; i <= count; i++)
            {
                items[i] = UrValue.Box(-1);
            }
            return new UrList(items);
        }
        items[0] = UrValue.Box(count);
        for (int i = 0; i < count; i++)
        {
            items[i + 1] = UrValue.Box(BinaryPrimitives.ReadInt32BigEndian(Pending.Slice(4 * i, 4)));
        }
        Consume(4 * count);
        var read = new UrList(items);
        Seam?.Read(this, read);
        return read;
    }

    /// <summary><c>socket_read_string</c>: the text that arrives within the timeout (empty when none does).</summary>
    public string ReadString(double timeoutSeconds, CancellationToken cancellation)
    {
        Fill(1, timeoutSeconds, cancellation);
        string text = Encoding.Latin1.GetString(Pending);
        Consume(Buffered);
        return text;
    }

    /// <summary>
    /// <c>socket_read_ascii_float</c>: reads text <c>(a, b, …)</c> and gives [n, a, b, …]; [0, nan …] when n numbers did not arrive in time.
    /// </summary>
    public UrList ReadAsciiFloats(int count, double timeoutSeconds, CancellationToken cancellation)
    {
        var failed = new object[count + 1];
        failed[0] = 0;
        for (int i = 1; i <= count; i++)
        {
            failed[i] = double.NaN;
        }
        int close;
        while ((close = Pending.IndexOf((byte)')')) < 0)
        {
            int have = Buffered;
            if (!Fill(have + 1, timeoutSeconds, cancellation))
            {
                return new UrList(failed);
            }
        }
        string text = Encoding.Latin1.GetString(Pending[..(close + 1)]);
        Consume(close + 1);
        int open = text.IndexOf('(', StringComparison.Ordinal);
        string[] parts = text[(open + 1)..^1].Split(',', StringSplitOptions.TrimEntries);
        if (open < 0 || parts.Length != count)
        {
            return new UrList(failed);
        }
        var items = new object[count + 1];
        items[0] = count;
        for (int i = 0; i < count; i++)
        {
            if (!double.TryParse(parts[i], System.Globalization.NumberStyles.Float, System.Globalization.CultureInfo.InvariantCulture, out double v))
            {
                return new UrList(failed);
            }
            items[i + 1] = v;
        }
        return new UrList(items);
    }

    /// <summary>Sends bytes for the program, through the <see cref="Seam"/> when there is one; false when the connection is gone.</summary>
    public bool Send(ReadOnlySpan<byte> bytes) => Seam is { } seam ? seam.Send(this, bytes, Program) : SendDirect(bytes);

    /// <summary>Sends bytes straight to the connection; false when it is gone.</summary>
    internal bool SendDirect(ReadOnlySpan<byte> bytes)
    {
        if (Held is { } held)
        {
            return held.TryWrite(bytes);
        }
        try
        {
            while (bytes.Length > 0)
            {
                int sent = socket.Send(bytes);
                bytes = bytes[sent..];
            }
            return true;
        }
        catch (SocketException)
        {
            return false;
        }
        catch (ObjectDisposedException)
        {
            return false;
        }
    }

    /// <summary><c>socket_send_int</c>: a big-endian signed 32-bit integer.</summary>
    public bool SendInt(int value)
    {
        Span<byte> bytes = stackalloc byte[4];
        BinaryPrimitives.WriteInt32BigEndian(bytes, value);
        return Send(bytes);
    }

    /// <inheritdoc/>
    public void Dispose()
    {
        Held?.Flush(); // what the stack still holds leaves before the connection closes
        socket.Dispose();
    }
}
