using System.Net.Sockets;

namespace Machina.Simulation.Twin;

/// <summary>
/// What the controller's network stack holds to send on one connection. As on a real controller, SocketSend (RAPID) or EKI_Send
/// (KRL) hands its bytes to the stack and returns, and the stack transmits beside the interpreter: bytes written on the thread that
/// owns <paramref name="sends"/> (the task that accepted the connection, the KRL robot interpreter) are held, in order, and go out in one write when that task is about to block in a wait, after
/// <see cref="TwinHeldSends.StatementBound"/> statements without one, once <see cref="SizeBound"/> bytes are held, before
/// SocketClose, when the task's run ends, and before the connection is dropped (<see cref="Flush"/>). Bytes written on any other
/// thread go out at once, after what is held. A write that fails marks the connection closed: the next write throws
/// <see cref="IOException"/> (the task's next SocketSend raises ERR_SOCK_CLOSED; its SocketReceive finds the connection closed).
/// </summary>
internal sealed class TwinHeldOutbox(Socket connection, TwinHeldSends sends) : Stream
{
    /// <summary>Held bytes that go out at once, without waiting for the task to wait.</summary>
    public const int SizeBound = 64 * 1024;

    private readonly Lock _gate = new();
    private byte[] _held = new byte[256];
    private int _count;
    private bool _failed;

    /// <inheritdoc/>
    public override bool CanRead => false;

    /// <inheritdoc/>
    public override bool CanSeek => false;

    /// <inheritdoc/>
    public override bool CanWrite => true;

    /// <inheritdoc/>
    public override long Length => throw new NotSupportedException();

    /// <inheritdoc/>
    public override long Position
    {
        get => throw new NotSupportedException();
        set => throw new NotSupportedException();
    }

    /// <summary>True while bytes are held (not yet written).</summary>
    public bool Holds
    {
        get
        {
            lock (_gate)
            {
                return _count > 0;
            }
        }
    }

    /// <summary>Holds <paramref name="buffer"/> (the task's thread) or writes it after what is held (any other thread).</summary>
    /// <exception cref="IOException">The connection is closed (a write failed).</exception>
    public override void Write(ReadOnlySpan<byte> buffer)
    {
        if (!TryWrite(buffer))
        {
            throw new IOException("The connection is closed.");
        }
    }

    /// <summary>
    /// <see cref="Write(ReadOnlySpan{byte})"/> without its exception: false when the connection is closed (a write failed, before
    /// or now). The twins' own sends take this path: a disconnect costs them no thrown exception.
    /// </summary>
    public bool TryWrite(ReadOnlySpan<byte> buffer)
    {
        lock (_gate)
        {
            if (_failed)
            {
                return false;
            }
            if (!sends.OwnedByCurrentThread)
            {
                FlushHeld();
                return Send(buffer);
            }
            if (_count + buffer.Length > _held.Length)
            {
                Array.Resize(ref _held, Math.Max(_held.Length * 2, _count + buffer.Length));
            }
            buffer.CopyTo(_held.AsSpan(_count));
            bool first = _count == 0;
            _count += buffer.Length;
            if (_count >= SizeBound)
            {
                FlushHeld();
                return true;
            }
            if (first && _count > 0)
            {
                sends.Hold(this);
            }
            return true;
        }
    }

    /// <inheritdoc/>
    public override void Write(byte[] buffer, int offset, int count) => Write(buffer.AsSpan(offset, count));

    /// <summary>Writes what is held in one write; a failure marks the connection closed (nothing is thrown here).</summary>
    public override void Flush()
    {
        lock (_gate)
        {
            FlushHeld();
        }
    }

    /// <inheritdoc/>
    public override int Read(byte[] buffer, int offset, int count) => throw new NotSupportedException();

    /// <inheritdoc/>
    public override long Seek(long offset, SeekOrigin origin) => throw new NotSupportedException();

    /// <inheritdoc/>
    public override void SetLength(long value) => throw new NotSupportedException();

    private void FlushHeld()
    {
        if (_count == 0)
        {
            return;
        }
        int count = _count;
        _count = 0;
        Send(_held.AsSpan(0, count));
        if (_held.Length > SizeBound)
        {
            _held = new byte[256]; // a large burst does not keep its buffer
        }
    }

    /// <summary>Writes <paramref name="bytes"/> whole (a blocking send); false, and the connection marked closed, when it fails.</summary>
    private bool Send(ReadOnlySpan<byte> bytes)
    {
        if (_failed)
        {
            return false;
        }
        try
        {
            // The overload that reports the error: a peer that closed (a broken pipe, a reset) is the usual end of a connection,
            // not worth a thrown exception per disconnect.
            connection.Send(bytes, SocketFlags.None, out SocketError error);
            if (error == SocketError.Success)
            {
                return true;
            }
        }
        catch (Exception e) when (e is SocketException or ObjectDisposedException)
        {
        }
        _failed = true;
        return false;
    }
}
