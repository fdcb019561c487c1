using System.Buffers.Binary;

namespace Machina.Simulation;

/// <summary>
/// Cuts the bytes an RTDE client sends into packages (size, type, payload), however TCP chunks them. A size below the header's
/// is refused: the stream cannot be read on.
/// </summary>
internal sealed class VirtualUrRtdeReader
{
    private byte[] _buffer = new byte[4096];
    private int _start;
    private int _length;

    /// <summary>Adds received bytes.</summary>
    public void Append(ReadOnlySpan<byte> data)
    {
        if (_start + _length + data.Length > _buffer.Length)
        {
            Array.Copy(_buffer, _start, _buffer, 0, _length);
            _start = 0;
            if (_length + data.Length > _buffer.Length)
            {
                Array.Resize(ref _buffer, Math.Max(_buffer.Length * 2, _length + data.Length));
            }
        }
        data.CopyTo(_buffer.AsSpan(_start + _length));
        _length += data.Length;
    }

    /// <summary>The next complete package, if one is there; the payload is valid until the next call.</summary>
    /// <exception cref="InvalidDataException">A package declares a size smaller than its header.</exception>
    public bool TryRead(out byte type, out ReadOnlySpan<byte> payload)
    {
        type = 0;
        payload = default;
        if (_length < VirtualUrRtdePackages.HeaderSize)
        {
            return false;
        }
        int size = BinaryPrimitives.ReadUInt16BigEndian(_buffer.AsSpan(_start));
        if (size < VirtualUrRtdePackages.HeaderSize)
        {
            throw new InvalidDataException($"an RTDE package declared {size} bytes, fewer than its {VirtualUrRtdePackages.HeaderSize}-byte header.");
        }
        if (_length < size)
        {
            return false;
        }
        type = _buffer[_start + 2];
        payload = _buffer.AsSpan(_start + VirtualUrRtdePackages.HeaderSize, size - VirtualUrRtdePackages.HeaderSize);
        _start += size;
        _length -= size;
        if (_length == 0)
        {
            _start = 0;
        }
        return true;
    }
}
