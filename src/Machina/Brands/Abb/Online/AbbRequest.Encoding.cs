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
        if (TryWriteShortDecimal(value, destination, out int written))
        {
            return written;
        }
        Num.Clean(value).TryFormat(destination, out written, "G15", Num.Inv);
        return written;
    }

    /// <summary>
    /// G15's text of a value that is the double nearest a decimal of at most four places below 10^10 (what the requests' rounding to
    /// 3 or 4 decimals gives: a move's numbers), written from that decimal's digits without the general formatter. Such a decimal has
    /// at most 14 significant digits, so the double's 15 significant digits are the decimal's own (a double holds 15 decimal digits
    /// both ways) and G15 prints it in fixed notation without trailing zeros. False, and nothing written, for any other value.
    /// </summary>
    internal static bool TryWriteShortDecimal(double value, Span<byte> destination, out int written)
    {
        written = 0;
        if (!(Math.Abs(value) < 1e10))
        {
            return false;
        }
        double scaled = Math.Round(value * 10000);
        // The division is correctly rounded, so equality says the value is the double nearest scaled / 10^4.
        if (scaled / 10000 != value)
        {
            return false;
        }
        long tenThousandths = (long)scaled;
        int n = 0;
        if (tenThousandths < 0)
        {
            destination[n++] = (byte)'-';
            tenThousandths = -tenThousandths;
        }
        long whole = tenThousandths / 10000;
        int fraction = (int)(tenThousandths - whole * 10000);
        whole.TryFormat(destination[n..], out int digits, default, Num.Inv);
        n += digits;
        if (fraction != 0)
        {
            destination[n++] = (byte)'.';
            for (int divisor = 1000; fraction != 0; divisor /= 10)
            {
                int digit = fraction / divisor;
                destination[n++] = (byte)('0' + digit);
                fraction -= digit * divisor;
            }
        }
        written = n;
        return true;
    }
}
