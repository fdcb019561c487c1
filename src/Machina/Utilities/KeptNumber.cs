namespace Machina;

/// <summary>
/// The text of the last number written (<see cref="NumShortest.WriteGeneral"/>, as <see cref="Num.G"/>), kept: a warning
/// repeated on every short move quotes the same blend radius each time and the same length twice in a row, which are then
/// copied instead of formatted again.
/// </summary>
/// <remarks>Values are compared by their bits, so that a text is reused only for exactly the number it was written from.</remarks>
internal sealed class KeptNumber
{
    private readonly byte[] _ascii = new byte[NumAppend.MaxChars];
    private int _length = -1;
    private long _bits;

    /// <summary>Writes the text of <paramref name="value"/> at <paramref name="at"/> as ASCII bytes; returns the position after it.</summary>
    internal int WriteAscii(Span<byte> destination, int at, double value)
    {
        long bits = BitConverter.DoubleToInt64Bits(value);
        if (_length < 0 || bits != _bits)
        {
            // The shortest digits straight as bytes; G15's general text (E notation, many digits) is written as characters and
            // narrowed: digits, a sign, a point and E notation's letter are ASCII.
            _length = NumShortest.TryWrite<byte>(_ascii, value);
            if (_length < 0)
            {
                Span<char> text = stackalloc char[NumAppend.MaxChars];
                _length = NumShortest.WriteGeneral(text, value);
                System.Text.Ascii.FromUtf16(text[.._length], _ascii, out _);
            }
            _bits = bits;
        }
        _ascii.AsSpan(0, _length).CopyTo(destination[at..]);
        return at + _length;
    }
}
