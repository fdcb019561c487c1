using System.Globalization;
using Machina.Simulation.Krl;

namespace Machina.Tests.Simulation.Krl;

/// <summary>
/// EKI_GetReal's plain decimal text read without the number parser (issue 45, perf52k): where the fast path reads a text it must
/// give the very double <see cref="double.Parse(string, IFormatProvider)"/> gives (bit for bit, -0 included), and it must leave
/// every other text (exponents, spaces, too many digits) to the parser.
/// </summary>
public class KrlDecimalTextTests
{
    [Theory]
    [InlineData("0", 0.0)]
    [InlineData("-0", -0.0)]
    [InlineData("12.375", 12.375)]
    [InlineData("-0.1", -0.1)]
    [InlineData("+4.5", 4.5)]
    [InlineData(".5", 0.5)]
    [InlineData("7.", 7.0)]
    [InlineData("0.3000000000000000", 0.3)]
    [InlineData("9007199254740992", 9007199254740992.0)]
    [InlineData("-1234.567890123", -1234.567890123)]
    public void PlainDecimalText_IsReadAsTheParserReadsIt(string text, double expected)
    {
        Assert.True(KrlDecimalText.TryRead(text, out double value));
        Assert.Equal(BitConverter.DoubleToInt64Bits(expected), BitConverter.DoubleToInt64Bits(value));
        Assert.Equal(BitConverter.DoubleToInt64Bits(double.Parse(text, CultureInfo.InvariantCulture)), BitConverter.DoubleToInt64Bits(value));
    }

    [Theory]
    [InlineData("")]
    [InlineData("-")]
    [InlineData(".")]
    [InlineData("1e3")]
    [InlineData(" 1.5")]
    [InlineData("1.5 ")]
    [InlineData("1,5")]
    [InlineData("1.2.3")]
    [InlineData("NaN")]
    [InlineData("9007199254740993")] // beyond 2^53: its double is not the whole number itself
    [InlineData("0.30000000000000004")] // 17 digits: beyond 2^53 as a whole number
    [InlineData("12345678901234567890")] // 20 digits
    [InlineData("0.00000000000000000000001")] // 23 decimals
    public void OtherText_IsLeftToTheParser(string text) => Assert.False(KrlDecimalText.TryRead(text, out _));

    [Fact]
    public void ManyNumbersAsTheHostAndOthersWriteThem_ReadBitForBitAsTheParser()
    {
        var random = new Random(52);
        int read = 0;
        for (int n = 0; n < 20_000; n++)
        {
            double source = (random.NextDouble() - 0.5) * Math.Pow(10, random.Next(-6, 12));
            string text = (n % 4) switch
            {
                0 => source.ToString("F3", CultureInfo.InvariantCulture),
                1 => source.ToString("F6", CultureInfo.InvariantCulture),
                2 => source.ToString("R", CultureInfo.InvariantCulture),
                _ => source.ToString("0.###############", CultureInfo.InvariantCulture),
            };
            double parsed = double.Parse(text, CultureInfo.InvariantCulture);
            if (KrlDecimalText.TryRead(text, out double value))
            {
                read++;
                Assert.True(BitConverter.DoubleToInt64Bits(parsed) == BitConverter.DoubleToInt64Bits(value), $"{text}: {value:R} instead of {parsed:R}");
            }
        }
        Assert.InRange(read, 9_000, 20_000); // the fixed forms (F3, most of F6) at least take the fast path
    }
}
