using System.Net.Sockets;

namespace Machina.Tests.Support;

internal sealed partial class FaultProxy
{
    private readonly List<HeldLink> _held = [];
    private int _holdNext;

    /// <summary>Connections whose bytes towards the controller are held now (not released yet).</summary>
    public int Holding
    {
        get
        {
            lock (_gate)
            {
                return _held.Count(h => h.Holding);
            }
        }
    }

    /// <summary>Bytes held now, on every held connection.</summary>
    public int HeldBytes
    {
        get
        {
            lock (_gate)
            {
                return _held.Sum(h => h.HeldBytes);
            }
        }
    }

    /// <summary>Holds what follows on every live connection of the fault channel (<see cref="FaultProxyOptions.Holdable"/>).</summary>
    public void HoldNow()
    {
        lock (_gate)
        {
            _held.ForEach(h => h.HoldNow());
        }
    }

    /// <summary>Holds the next <paramref name="count"/> connections of the fault channel from their first byte (<see cref="FaultProxyOptions.Holdable"/>).</summary>
    public void HoldNext(int count = 1) => Interlocked.Add(ref _holdNext, count);

    /// <summary>Closes the sending side of every connection that holds bytes; the receiving side stays open, its bytes still held.</summary>
    public void CutHeldSenders()
    {
        lock (_gate)
        {
            foreach (HeldLink link in _held.Where(h => h.Holding))
            {
                link.CutSender();
            }
        }
    }

    /// <summary>
    /// Delivers what every held connection holds to the controller and carries later bytes at once; a connection whose host is
    /// gone is then closed (the controller sees its end after the late bytes).
    /// </summary>
    public async Task ReleaseHeldAsync(CancellationToken cancellationToken = default)
    {
        HeldLink[] links;
        lock (_gate)
        {
            links = [.. _held];
        }
        foreach (HeldLink link in links)
        {
            await link.ReleaseAsync(cancellationToken);
        }
    }

    private HeldLink AddHeld(TcpClient sender, TcpClient receiver, long holdAt)
    {
        var link = new HeldLink(sender, receiver, holdAt);
        lock (_gate)
        {
            _held.RemoveAll(h => h.Finished);
            _held.Add(link);
        }
        return link;
    }

    /// <summary>True (once per <see cref="HoldNext"/>) when the connection starting now is to be held from its first byte.</summary>
    private bool TakeNextHold()
    {
        while (true)
        {
            int next = Volatile.Read(ref _holdNext);
            if (next <= 0)
            {
                return false;
            }
            if (Interlocked.CompareExchange(ref _holdNext, next - 1, next) == next)
            {
                return true;
            }
        }
    }

    private void ReleaseOnStop()
    {
        lock (_gate)
        {
            _held.ForEach(h => h.Abandon());
        }
    }

    /// <summary>One direction of a connection, holding its bytes from a point on until released.</summary>
    private sealed class HeldLink(TcpClient sender, TcpClient receiver, long holdAt)
    {
        private long _holdAt = holdAt;
        private long _carried;
        private volatile bool _finished;

        private readonly SemaphoreSlim _write = new(1, 1);
        private readonly MemoryStream _held = new();
        private readonly TaskCompletionSource _released = new(TaskCreationOptions.RunContinuationsAsynchronously);
        private volatile bool _holding;
        private long _heldCount;

        /// <summary>Bytes are held and not released yet.</summary>
        public bool Holding => _holding && !_released.Task.IsCompleted;

        /// <summary>How many bytes are held now.</summary>
        public int HeldBytes => Holding ? (int)Interlocked.Read(ref _heldCount) : 0;

        /// <summary>The pump has ended (the connection is over).</summary>
        public bool Finished => _finished;

        /// <summary>Holds from the next byte on (nothing if the link holds already or was released).</summary>
        public void HoldNow()
        {
            _write.Wait();
            try
            {
                if (!_released.Task.IsCompleted)
                {
                    _holdAt = Math.Min(_holdAt, _carried);
                }
            }
            finally
            {
                _write.Release();
            }
        }

        /// <summary>Carries the sender's bytes, holding them from the hold point on; after the sender ends, waits for the release of what it holds. Returns how many bytes the sender sent.</summary>
        public async Task<long> PumpAsync(CancellationToken token)
        {
            var buffer = new byte[4096];
            try
            {
                NetworkStream input = sender.GetStream();
                NetworkStream output = receiver.GetStream();
                while (true)
                {
                    int n;
                    try
                    {
                        n = await input.ReadAsync(buffer, token);
                    }
                    catch (Exception e) when (e is IOException or SocketException or ObjectDisposedException)
                    {
                        n = 0;
                    }
                    if (n == 0)
                    {
                        break;
                    }
                    await _write.WaitAsync(token);
                    try
                    {
                        int pass = _released.Task.IsCompleted ? n : (int)Math.Clamp(_holdAt - _carried, 0, n);
                        if (pass > 0)
                        {
                            await output.WriteAsync(buffer.AsMemory(0, pass), token);
                        }
                        if (pass < n)
                        {
                            _held.Write(buffer, pass, n - pass);
                            Interlocked.Add(ref _heldCount, n - pass);
                            _holding = true;
                        }
                        _carried += n;
                    }
                    finally
                    {
                        _write.Release();
                    }
                }
                if (_holding)
                {
                    await _released.Task.WaitAsync(token);
                }
            }
            catch (Exception e) when (e is IOException or SocketException or OperationCanceledException or ObjectDisposedException)
            {
                // The receiver left, or the proxy stops.
            }
            finally
            {
                _finished = true;
            }
            return Interlocked.Read(ref _carried);
        }

        public void CutSender() => sender.Dispose();

        /// <summary>Delivers what is held and carries later bytes at once; a link that holds nothing only forgets a hold asked for.</summary>
        public async Task ReleaseAsync(CancellationToken token)
        {
            await _write.WaitAsync(token);
            try
            {
                if (_released.Task.IsCompleted)
                {
                    return;
                }
                if (!_holding)
                {
                    _holdAt = long.MaxValue;
                    return;
                }
                await receiver.GetStream().WriteAsync(_held.GetBuffer().AsMemory(0, (int)_held.Length), token);
                _released.TrySetResult();
            }
            catch (Exception e) when (e is IOException or SocketException or ObjectDisposedException or InvalidOperationException)
            {
                // The receiver is gone: nothing to deliver to.
                _released.TrySetResult();
            }
            finally
            {
                _write.Release();
            }
        }

        public void Abandon() => _released.TrySetResult();
    }
}
