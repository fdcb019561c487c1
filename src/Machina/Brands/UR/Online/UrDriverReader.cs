using System.Buffers.Binary;

namespace Machina;

/// <summary>
/// Reads what Machina's URScript driver sends back (docs/protocol-ur.md): big-endian int32 values, however TCP chunks them. A
/// value above 0 acknowledges that id; a value below -1 starts a response (its code) that runs until <see cref="UrWire.End"/>;
/// 0 and -1 mean nothing. A response longer than <see cref="MaxResponseValues"/> values throws <see cref="RobotConnectionException"/>,
/// so garbage never grows memory. Not thread-safe: one reader per connection, used by its receive loop.
/// </summary>
internal sealed class UrDriverReader : IMessageReader<UrReply>
{
    /// <summary>Most values a response may hold, its code included (the longest, the full pose, has 13).</summary>
    internal const int MaxResponseValues = 64;

    private readonly byte[] _partial = new byte[4];
    private readonly List<int> _response = new(16);
    private int _partialLength;
    private bool _inResponse;
    private byte[] _pending = new byte[256];
    private int _pendingStart;
    private int _pendingEnd;

    /// <summary>Keeps received bytes for <see cref="TryRead(out UrReply)"/>.</summary>
    public void Append(ReadOnlySpan<byte> data)
    {
        if (_pendingStart == _pendingEnd)
        {
            _pendingStart = _pendingEnd = 0;
        }
        ReceiveBuffer.Append(ref _pending, ref _pendingStart, ref _pendingEnd, data);
    }

    /// <summary>The next acknowledgement or response from the appended bytes, or false when more are needed.</summary>
    /// <exception cref="RobotConnectionException">A response that never ends: this is not Machina's driver.</exception>
    public bool TryRead(out UrReply reply)
    {
        ReadOnlySpan<byte> rest = _pending.AsSpan(_pendingStart, _pendingEnd - _pendingStart);
        int before = rest.Length;
        bool read = TryRead(ref rest, out int acknowledged, out int[]? response);
        _pendingStart += before - rest.Length;
        reply = new UrReply(acknowledged, response);
        return read;
    }

    /// <summary>
    /// Consumes bytes from <paramref name="data"/> until a message is complete (true) or the bytes run out (false). A message is
    /// an acknowledgement (<paramref name="acknowledged"/> above 0, <paramref name="response"/> null) or a response (its values,
    /// code first, without the end marker).
    /// </summary>
    /// <exception cref="RobotConnectionException">A response that never ends: this is not Machina's driver.</exception>
    internal bool TryRead(ref ReadOnlySpan<byte> data, out int acknowledged, out int[]? response)
    {
        acknowledged = 0;
        response = null;
        while (!data.IsEmpty)
        {
            int take = Math.Min(4 - _partialLength, data.Length);
            data[..take].CopyTo(_partial.AsSpan(_partialLength));
            _partialLength += take;
            data = data[take..];
            if (_partialLength < 4)
            {
                break;
            }
            _partialLength = 0;
            int value = BinaryPrimitives.ReadInt32BigEndian(_partial);
            if (_inResponse)
            {
                if (value == UrWire.End)
                {
                    _inResponse = false;
                    response = [.. _response];
                    return true;
                }
                if (_response.Count >= MaxResponseValues)
                {
                    throw new RobotConnectionException($"The UR driver sent a response longer than {MaxResponseValues} values that never ends; is it Machina's driver?");
                }
                _response.Add(value);
            }
            else if (value < -1)
            {
                _inResponse = true;
                _response.Clear();
                _response.Add(value);
            }
            else if (value > 0)
            {
                acknowledged = value;
                return true;
            }
        }
        return false;
    }
}

/// <summary>One message from Machina's URScript driver: an acknowledgement (<paramref name="Acknowledged"/> above 0) or a response.</summary>
/// <param name="Acknowledged">The id acknowledged, or 0 for a response.</param>
/// <param name="Response">The response's values, code first, or null for an acknowledgement.</param>
internal readonly record struct UrReply(int Acknowledged, int[]? Response);
