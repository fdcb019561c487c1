using System.Text;

namespace Machina.Tests.Utilities;

public class NumAppendTests
{
    [Theory]
    [InlineData(400, 3, "400")]
    [InlineData(0.70710678, 4, "0.7071")]
    [InlineData(-0.00001, 3, "0")]
    [InlineData(-12.3456, 3, "-12.346")]
    [InlineData(0.0025, 3, "0.002")]
    [InlineData(0.005, 6, "0.005")]
    [InlineData(0.00001, 6, "0.00001")]
    [InlineData(1.5707963267948966, 6, "1.570796")]
    [InlineData(1e20, 3, "100000000000000000000")]
    public void AppendFixed_Value_PrintsRoundedPlainDecimal(double value, int decimals, string expected)
    {
        Assert.Equal(expected, new StringBuilder().AppendFixed(value, decimals).ToString());
    }

    [Fact]
    public void AppendFixed_ManyValues_MatchNumF()
    {
        var random = new Random(12345);
        for (int i = 0; i < 200_000; i++)
        {
            int decimals = 3 + i % 4;
            double value = (random.NextDouble() - 0.5) * Math.Pow(10, random.Next(-3, 7));
            string fast = new StringBuilder().AppendFixed(value, decimals).ToString();
            string reference = Num.F(value, decimals);
            if (!reference.Contains('E', StringComparison.Ordinal))
            {
                Assert.Equal(reference, fast);
            }
        }
    }

    [Fact]
    public void AppendFixed_OneBuilderFillingUp_SameTextAsSeparateNumbers()
    {
        // The digits go straight into the builder's free space when it has room for any number, and through a buffer of
        // the builder's own when it has not (a fresh builder, a chunk nearly full): both give the number's text.
        var random = new Random(28);
        var builder = new StringBuilder(4);
        var expected = new StringBuilder();
        for (int i = 0; i < 20_000; i++)
        {
            int decimals = i % 10;
            double value = Math.Round((random.NextDouble() - 0.5) * Math.Pow(10, random.Next(-2, 12)), 9);
            string alone = new StringBuilder().AppendFixed(value, decimals).ToString();
            string reference = Num.F(value, decimals);
            if (!reference.Contains('E', StringComparison.Ordinal))
            {
                Assert.Equal(reference, alone);
            }
            builder.AppendFixed(value, decimals).Append(i % 7 == 0 ? "|" : "");
            expected.Append(alone).Append(i % 7 == 0 ? "|" : "");
        }
        Assert.Equal(expected.ToString(), builder.ToString());
    }

    [Theory]
    [InlineData(1.000000001, 9, "1.000000001")]
    [InlineData(-0.000000005, 9, "-0.000000005")]
    [InlineData(123456789012.5, 3, "123456789012.5")]
    [InlineData(999999999999999, 0, "999999999999999")]
    [InlineData(100.01, 2, "100.01")]
    [InlineData(10, 1, "10")]
    [InlineData(7, 0, "7")]
    public void AppendFixed_LongAndShortDigitRuns_EveryDigitInPlace(double value, int decimals, string expected)
    {
        Assert.Equal(expected, new StringBuilder().AppendFixed(value, decimals).ToString());
    }

    [Fact]
    public void WriteDecimal_EveryDigitCountAndDecimals_AsTheIntegerFormatter()
    {
        // The digit count comes from the highest bit and one comparison: the numbers on both sides of each power of ten and
        // of two, and random ones, at 0 to 9 decimals.
        var values = new List<long> { 0, long.MaxValue };
        long power = 1;
        for (int k = 0; k <= 18; k++, power *= 10)
        {
            values.AddRange([power - 1, power, power + 1]);
        }
        for (int bit = 0; bit < 63; bit++)
        {
            values.AddRange([(1L << bit) - 1, 1L << bit]);
        }
        var random = new Random(26);
        for (int i = 0; i < 20_000; i++)
        {
            values.Add(random.NextInt64(0, (long)Math.Pow(10, random.Next(1, 16))));
        }
        Span<char> buffer = stackalloc char[NumAppend.MaxChars];
        foreach (long value in values)
        {
            for (int decimals = 0; decimals <= 9; decimals++)
            {
                Assert.Equal(Expected(value, decimals, false), new string(buffer[..NumAppend.WriteDecimal(buffer, false, value, decimals)]));
                Assert.Equal(Expected(value, decimals, true), new string(buffer[..NumAppend.WriteDecimal(buffer, true, value, decimals)]));
            }
        }

        static string Expected(long value, int decimals, bool negative)
        {
            string digits = value.ToString(System.Globalization.CultureInfo.InvariantCulture).PadLeft(decimals + 1, '0');
            string whole = digits[..^decimals], fraction = digits[^decimals..].TrimEnd('0');
            return (negative && value != 0 ? "-" : "") + whole + (fraction.Length > 0 ? "." + fraction : "");
        }
    }

    [Fact]
    public void WriteDecimal_MillimetresAndMetresBelowThousand_AsTheIntegerFormatter()
    {
        // The three-digit groups of 3 and 6 decimals: every mantissa at 3 decimals, and at 6 decimals each fraction with many
        // whole parts, plus the edges where the groups end.
        Span<char> buffer = stackalloc char[NumAppend.MaxChars];
        for (long value = 0; value <= 1_000_001; value++)
        {
            Check(buffer, value, 3);
        }
        var random = new Random(27);
        for (long fraction = 0; fraction < 1_000_000; fraction++)
        {
            Check(buffer, random.Next(0, 1001) * 1_000_000L + fraction, 6);
        }
        foreach (long value in new long[] { 999_999_999, 1_000_000_000, 1_000_000_001, 999_000_000, 1_999_999_999 })
        {
            Check(buffer, value, 6);
        }

        static void Check(Span<char> buffer, long value, int decimals)
        {
            string digits = value.ToString(System.Globalization.CultureInfo.InvariantCulture).PadLeft(decimals + 1, '0');
            string whole = digits[..^decimals], fraction = digits[^decimals..].TrimEnd('0');
            string expected = whole + (fraction.Length > 0 ? "." + fraction : "");
            if (!buffer[..NumAppend.WriteDecimal(buffer, false, value, decimals)].SequenceEqual(expected)
                || !buffer[..NumAppend.WriteDecimal(buffer, true, value, decimals)].SequenceEqual(value == 0 ? expected : "-" + expected))
            {
                Assert.Fail($"{value} at {decimals} decimals: expected {expected}, got {new string(buffer[..NumAppend.WriteDecimal(buffer, false, value, decimals)])}");
            }
        }
    }

    [Fact]
    public void RoundEven_ValuesBelow2To51_SameAsMathRound()
    {
        var random = new Random(25);
        for (int i = 0; i < 200_000; i++)
        {
            double value = (random.NextDouble() - 0.5) * Math.Pow(10, random.Next(-3, 16));
            // (Math.Round keeps the sign of a negative value that rounds to 0; RoundEven gives +0: equal numbers.)
            Assert.Equal(Math.Round(value), NumAppend.RoundEven(value), 0.0);
        }
        // Halves go to the even neighbour, as Math.Round does.
        Assert.Equal([0, 2, 2, -2, -2, 4], new[] { 0.5, 1.5, 2.5, -1.5, -2.5, 3.5 }.Select(NumAppend.RoundEven));
        Assert.Equal(2251799813685246.0, NumAppend.RoundEven(2251799813685246.5));
        Assert.Equal(2251799813685244.0, NumAppend.RoundEven(2251799813685244.25));
    }

    [Theory]
    [InlineData(1e15)]
    [InlineData(-1e15)]
    [InlineData(1e300)]
    [InlineData(double.PositiveInfinity)]
    [InlineData(double.NegativeInfinity)]
    public void RoundEven_HugeValues_StayHugeForTheCallersCheck(double value)
    {
        Assert.True(Math.Abs(NumAppend.RoundEven(value)) >= 1e15);
        Assert.Equal(-1, NumAppend.TryWriteScaled(new char[NumAppend.MaxChars], value, 0));
    }

    [Fact]
    public void RoundEven_NaN_IsNaNAndRefusedByTryWriteScaled()
    {
        Assert.True(double.IsNaN(NumAppend.RoundEven(double.NaN)));
        Assert.Equal(-1, NumAppend.TryWriteScaled(new char[NumAppend.MaxChars], double.NaN, 3));
    }

    [Fact]
    public void TryWriteScaledAscii_ManyValues_TheBytesOfTheCharactersTryWriteScaledWrites()
    {
        // Both halves of the fast digits (3 and 6 decimals below 1000 units), the general digits, huge and refused values.
        var random = new Random(48);
        var values = new List<double> { 0, -0.0, 0.0005, -0.0005, 999.9995, 1e15, -1e15, 1e20, double.NaN, double.PositiveInfinity };
        for (int i = 0; i < 20_000; i++)
        {
            values.Add((random.NextDouble() - 0.5) * Math.Pow(10, random.Next(-4, 14)));
        }
        Span<char> chars = stackalloc char[NumAppend.MaxChars];
        Span<byte> bytes = stackalloc byte[NumAppend.MaxChars];
        foreach (double value in values)
        {
            for (int decimals = 0; decimals <= NumAppend.MaxDecimals; decimals++)
            {
                int charCount = NumAppend.TryWriteScaled(chars, value, decimals);
                int byteCount = NumAppend.TryWriteScaledAscii(bytes, value, decimals);
                Assert.Equal(charCount, byteCount);
                if (charCount > 0)
                {
                    Assert.Equal(new string(chars[..charCount]), Encoding.ASCII.GetString(bytes[..byteCount]));
                }
            }
        }
    }

    [Theory]
    [InlineData(300.0, 0.0, 500.0, 0.001, 6)]
    [InlineData(-1.23456789, 987.654321, -0.0004, 1.0, 3)]
    [InlineData(1e20, 1, 2, 1.0, 3)]
    public void TryWriteCoordinatesAscii_Position_TheBytesOfTheCharactersTryWriteCoordinatesWrites(double x, double y, double z, double scale, int decimals)
    {
        var position = new Vector(x, y, z);
        var chars = new char[8 + 3 * (NumAppend.MaxChars + 2)];
        var bytes = new byte[chars.Length];
        "p[".CopyTo(chars);
        "p["u8.CopyTo(bytes);

        int charEnd = NumAppend.TryWriteCoordinates(chars, 2, position, scale, decimals, ", ");
        int byteEnd = NumAppend.TryWriteCoordinatesAscii(bytes, 2, position, scale, decimals, ", "u8);

        Assert.Equal(charEnd, byteEnd);
        if (charEnd > 0)
        {
            Assert.Equal(new string(chars, 0, charEnd), Encoding.ASCII.GetString(bytes, 0, byteEnd));
        }
        Assert.Equal(x < 1e15, charEnd > 0);
    }
}
