using System.Buffers.Binary;
using System.Text;

namespace Machina.Simulation;

/// <summary>
/// Writes the big-endian values UR's interfaces carry (client interface packages, RTDE) into a buffer of its own that grows as
/// needed and can be reused from package to package; each protocol's framing (its size fields) is a subclass.
/// </summary>
internal abstract class VirtualUrWriter(int capacity)
{
    private byte[] _bytes = new byte[Math.Max(capacity, 1)];

    /// <summary>Bytes written so far.</summary>
    protected int Length { get; private set; }

    /// <summary>A BOOL or UINT8.</summary>
    public void Byte(byte value) => Next(1)[0] = value;

    /// <summary>A boolean as one byte (1 or 0).</summary>
    public void Bool(bool value) => Byte(value ? (byte)1 : (byte)0);

    /// <summary>An INT32.</summary>
    public void Int32(int value) => BinaryPrimitives.WriteInt32BigEndian(Next(4), value);

    /// <summary>A UINT32.</summary>
    public void UInt32(uint value) => BinaryPrimitives.WriteUInt32BigEndian(Next(4), value);

    /// <summary>A UINT64.</summary>
    public void UInt64(ulong value) => BinaryPrimitives.WriteUInt64BigEndian(Next(8), value);

    /// <summary>A float (4 bytes).</summary>
    public void Float(float value) => BinaryPrimitives.WriteSingleBigEndian(Next(4), value);

    /// <summary>A DOUBLE.</summary>
    public void Double(double value) => BinaryPrimitives.WriteDoubleBigEndian(Next(8), value);

    /// <summary>Doubles one after the other (a VECTOR3D, a VECTOR6D).</summary>
    public void Doubles(ReadOnlySpan<double> values)
    {
        foreach (double value in values)
        {
            Double(value);
        }
    }

    /// <summary>Bytes as they are.</summary>
    public void Bytes(ReadOnlySpan<byte> bytes) => bytes.CopyTo(Next(bytes.Length));

    /// <summary>Text in ASCII.</summary>
    public void Ascii(string text) => Encoding.ASCII.GetBytes(text, Next(Encoding.ASCII.GetByteCount(text)));

    /// <summary>Zero bytes: values the twin does not model.</summary>
    public void Zeros(int bytes) => Next(bytes).Clear();

    /// <summary>Doubles of 0.</summary>
    public void ZeroDoubles(int count) => Zeros(count * 8);

    /// <summary>Drops what was written from <paramref name="length"/> on: the next value goes there.</summary>
    protected void Restart(int length) => Length = length;

    /// <summary>The bytes at <paramref name="at"/>, already written, to fill in a size.</summary>
    protected Span<byte> Written(int at, int count) => _bytes.AsSpan(at, count);

    /// <summary>Everything written, in the writer's buffer (valid until the next write).</summary>
    protected ReadOnlyMemory<byte> All => _bytes.AsMemory(0, Length);

    /// <summary>The next <paramref name="count"/> bytes, the buffer grown when they do not fit.</summary>
    private Span<byte> Next(int count)
    {
        if (Length + count > _bytes.Length)
        {
            Array.Resize(ref _bytes, Math.Max(_bytes.Length * 2, Length + count));
        }
        Span<byte> span = _bytes.AsSpan(Length, count);
        Length += count;
        return span;
    }
}
