using System.Net.Sockets;
using Machina.Simulation.Twin;

namespace Machina.Simulation.Krl;

/// <summary>
/// What EKI_Send hands to the EthernetKRL stack for one connection: the program goes on at once, as on a KR C4, where the
/// EthernetKRL process writes to the network beside the interpreter; a writer sends, in order, everything posted meanwhile in
/// one write. After a write failed (the connection broke) nothing more is taken.
/// </summary>
internal sealed class EkiOutbox(Stream stream)
{
    private readonly Lock _gate = new();
    private byte[] _pending = new byte[4096];
    private byte[] _spare = new byte[4096];
    private int _count;
    private Task? _writer;
    private bool _broken;

    /// <summary>Queues <paramref name="bytes"/> for the connection; false once a write failed.</summary>
    public bool Post(ReadOnlySpan<byte> bytes)
    {
        lock (_gate)
        {
            if (_broken)
            {
                return false;
            }
            if (_count + bytes.Length > _pending.Length)
            {
                Array.Resize(ref _pending, Math.Max(_pending.Length * 2, _count + bytes.Length));
            }
            bytes.CopyTo(_pending.AsSpan(_count));
            _count += bytes.Length;
            if (_writer is null)
            {
                _writer = Task.Run(Write);
            }
        }
        return true;
    }

    /// <summary>
    /// Waits until everything posted has been written or the connection broke (before the channel closes it, as EKI_Close
    /// sends what EKI_Send queued). The same wait a synchronous EKI_Send had. False when <paramref name="cancellation"/> ended
    /// the wait first (a client that reads nothing blocks the writer: the program's stop must not wait for it).
    /// </summary>
    public bool Drain(CancellationToken cancellation)
    {
        while (true)
        {
            Task? writer;
            lock (_gate)
            {
                writer = _writer;
            }
            if (writer is null)
            {
                return true;
            }
            try
            {
                TwinWait.For(writer, cancellation);
            }
            catch (OperationCanceledException) when (cancellation.IsCancellationRequested)
            {
                return false;
            }
        }
    }

    private void Write()
    {
        while (true)
        {
            byte[] chunk;
            int count;
            lock (_gate)
            {
                if (_count == 0 || _broken)
                {
                    _writer = null;
                    return;
                }
                (chunk, count) = (_pending, _count);
                (_pending, _count) = (_spare, 0);
            }
            try
            {
                stream.Write(chunk, 0, count);
            }
            catch (Exception e) when (e is IOException or SocketException or ObjectDisposedException or InvalidOperationException)
            {
                lock (_gate)
                {
                    _broken = true;
                    _writer = null;
                }
                return;
            }
            lock (_gate)
            {
                _spare = chunk;
            }
        }
    }
}
