using System.Buffers.Binary;

namespace Machina.Simulation;

/// <summary>
/// Reads one RTDE client's packages from its stream, one at a time, blocking: the header, then exactly the payload it
/// announces. The buffers are the reader's own and reused (a payload is valid until the next read).
/// </summary>
internal sealed class VirtualUrRtdeReader(Stream stream)
{
    private readonly byte[] _header = new byte[VirtualUrRtdePackages.HeaderSize];
    private byte[] _payload = new byte[256];

    /// <summary>The payload of the package read last.</summary>
    public ReadOnlySpan<byte> Payload => _payload.AsSpan(0, _length);

    private int _length;

    /// <summary>The type of the next package (its payload in <see cref="Payload"/>), or null when the client closed the connection, before or inside a package.</summary>
    /// <exception cref="InvalidDataException">A package declares a size smaller than its header: the stream cannot be read on.</exception>
    public byte? Read()
    {
        if (!Fill(_header))
        {
            return null;
        }
        int size = BinaryPrimitives.ReadUInt16BigEndian(_header);
        if (size < VirtualUrRtdePackages.HeaderSize)
        {
            throw new InvalidDataException($"an RTDE package declared {size} bytes, fewer than its {VirtualUrRtdePackages.HeaderSize}-byte header.");
        }
        _length = size - VirtualUrRtdePackages.HeaderSize;
        if (_payload.Length < _length)
        {
            _payload = new byte[Math.Max(_length, _payload.Length * 2)];
        }
        return Fill(_payload.AsSpan(0, _length)) ? _header[2] : null;
    }

    /// <summary>Reads exactly the bytes of <paramref name="into"/>; false when the stream ends first.</summary>
    private bool Fill(Span<byte> into) => into.Length == 0 || stream.ReadAtLeast(into, into.Length, throwOnEndOfStream: false) == into.Length;
}
