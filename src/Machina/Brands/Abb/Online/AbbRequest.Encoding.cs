using System.Text;

namespace Machina;

internal readonly partial struct AbbRequest
{
    /// <summary>Upper bound of the encoded length in bytes, to size a buffer before <see cref="EncodeTo(Span{byte})"/>.</summary>
    public int MaxEncodedLength =>
        16 + (RawStatement?.Length ?? 0) + (Text is null ? 0 : Text.Length + 3) + ParameterCount * 26;

    /// <summary>Writes the ASCII wire text (<c>@id code "text" p1 … pN;</c>) and returns the number of bytes written.</summary>
    public int EncodeTo(Span<byte> destination)
    {
        if (destination.Length < MaxEncodedLength)
        {
            throw new ArgumentException($"The buffer needs at least {MaxEncodedLength} bytes.", nameof(destination));
        }
        int n = 0;
        destination[n++] = (byte)'@';
        Id.TryFormat(destination[n..], out int written, default, Num.Inv);
        n += written;
        destination[n++] = (byte)' ';
        if (RawStatement is not null)
        {
            n += Encoding.ASCII.GetBytes(RawStatement, destination[n..]);
            destination[n++] = (byte)';';
            return n;
        }
        Code.TryFormat(destination[n..], out written, default, Num.Inv);
        n += written;
        if (Text is not null)
        {
            destination[n++] = (byte)' ';
            destination[n++] = (byte)'"';
            n += Encoding.ASCII.GetBytes(Text, destination[n..]);
            destination[n++] = (byte)'"';
        }
        for (int i = 0; i < ParameterCount; i++)
        {
            destination[n++] = (byte)' ';
            n += FormatNumber(_values[i], destination[n..]);
        }
        destination[n++] = (byte)';';
        return n;
    }

    /// <summary>Appends the wire bytes to <paramref name="writer"/> (for a send loop) and returns their count.</summary>
    public int EncodeTo(System.Buffers.IBufferWriter<byte> writer)
    {
        ArgumentNullException.ThrowIfNull(writer);
        int count = EncodeTo(writer.GetSpan(MaxEncodedLength));
        writer.Advance(count);
        return count;
    }

    /// <summary>The wire text as a string, e.g. <c>@12 1 400 0 500 0 0 1 0;</c>.</summary>
    public string ToWireText()
    {
        Span<byte> buffer = MaxEncodedLength <= 512 ? stackalloc byte[MaxEncodedLength] : new byte[MaxEncodedLength];
        int n = EncodeTo(buffer);
        return Encoding.ASCII.GetString(buffer[..n]);
    }

    /// <inheritdoc/>
    public override string ToString() => ToWireText();

    /// <summary>Prints a number like the original host: shortest G15 invariant text, the unused-axis value as <c>9E9</c>.</summary>
    internal static int FormatNumber(double value, Span<byte> destination)
    {
        if (value == UnusedAxis)
        {
            return System.Text.Encoding.ASCII.GetBytes(RapidFacts.UnusedAxisText, destination);
        }
        Num.Clean(value).TryFormat(destination, out int written, "G15", Num.Inv);
        return written;
    }
}
