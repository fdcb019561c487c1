namespace Machina;

/// <summary>
/// A number already scaled and rounded to a whole count of 10^−decimals (<see cref="NumAppend.TryWriteScaled"/>'s first two
/// steps), formatted straight into a builder's free space: <c>sb.Append($"{new ScaledDecimal(…)}")</c> lets the builder hand
/// its chunk to <see cref="TryFormat"/>, so the digits are not written to a stack buffer and copied.
/// </summary>
internal readonly struct ScaledDecimal(double scaled, int decimals) : ISpanFormattable
{
    /// <summary>Writes the text of <see cref="NumAppend.WriteDecimal"/>; false when <paramref name="destination"/> may be too short.</summary>
    public bool TryFormat(Span<char> destination, out int charsWritten, ReadOnlySpan<char> format, IFormatProvider? provider)
    {
        if (destination.Length < NumAppend.MaxChars)
        {
            charsWritten = 0;
            return false; // the builder formats into a larger buffer of its own and copies
        }
        charsWritten = NumAppend.WriteDecimal(destination, scaled < 0, (long)Math.Abs(scaled), decimals);
        return true;
    }

    /// <inheritdoc/>
    public string ToString(string? format, IFormatProvider? formatProvider) => ToString();

    /// <inheritdoc/>
    public override string ToString()
    {
        Span<char> buffer = stackalloc char[NumAppend.MaxChars];
        return new string(buffer[..NumAppend.WriteDecimal(buffer, scaled < 0, (long)Math.Abs(scaled), decimals)]);
    }
}
