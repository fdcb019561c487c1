namespace Machina.Simulation.Rapid;

/// <summary>A <c>rawbytes</c>: a container of up to 1024 bytes and its current length (the highest byte written or received).</summary>
internal sealed class RapidRawBytes
{
    /// <summary>The most bytes a rawbytes holds.</summary>
    public const int Capacity = 1024;

    /// <summary>The bytes (index 1 of RAPID is element 0).</summary>
    public byte[] Bytes { get; } = new byte[Capacity];

    /// <summary>How many bytes are valid (RawBytesLen).</summary>
    public int Length { get; set; }

    /// <summary>Writes <paramref name="data"/> from 1-based <paramref name="start"/>; the length grows to the last byte written.</summary>
    public void Write(int start, ReadOnlySpan<byte> data)
    {
        data.CopyTo(Bytes.AsSpan(start - 1));
        Length = Math.Max(Length, start - 1 + data.Length);
    }
}
