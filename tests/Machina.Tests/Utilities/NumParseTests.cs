using System.Globalization;

namespace Machina.Tests.Utilities;

/// <summary>The fast number reader of instruction text returns exactly the double of the general parser, and declines the rest.</summary>
public class NumParseTests
{
    private static bool General(string text, out double value) => double.TryParse(text, NumberStyles.Float, CultureInfo.InvariantCulture, out value);

    [Theory]
    [InlineData("12.5")]
    [InlineData("-0.125")]
    [InlineData("+7")]
    [InlineData("1.")]
    [InlineData(".5")]
    [InlineData("-0")]
    [InlineData("0.1")]
    [InlineData("123456789012345")]
    [InlineData("0.000000000000001")]
    [InlineData("9007199254740993")]
    [InlineData("1e3")]
    [InlineData("1E-05")]
    [InlineData(" 4")]
    [InlineData("Infinity")]
    public void TryParse_Text_SameBitsAsGeneralParser(string text)
    {
        bool expectedOk = General(text, out double expected);
        bool ok = NumParse.TryParse(text, out double value);
        Assert.Equal(expectedOk, ok);
        Assert.Equal(BitConverter.DoubleToInt64Bits(expected), BitConverter.DoubleToInt64Bits(value));
    }

    [Theory]
    [InlineData("")]
    [InlineData("-")]
    [InlineData(".")]
    [InlineData("1.2.3")]
    [InlineData("--1")]
    [InlineData("1,5")]
    [InlineData("abc")]
    public void TryParse_NotANumber_FalseLikeGeneralParser(string text)
    {
        Assert.False(General(text, out _));
        Assert.False(NumParse.TryParse(text, out _));
    }

    [Theory]
    [InlineData("1234567890123456", false)]
    [InlineData("1e3", false)]
    [InlineData("-8.07", true)]
    public void TryParseShort_Form_TakenOnlyForPlainShortNumbers(string text, bool taken)
    {
        Assert.Equal(taken, NumParse.TryParseShort(text, out _));
    }

    [Fact]
    public void TryParse_RandomDecimals_SameBitsAsGeneralParser()
    {
        var random = new Random(31);
        int shortForm = 0;
        for (int i = 0; i < 200_000; i++)
        {
            double value = Math.Round((random.NextDouble() - 0.5) * Math.Pow(10, random.Next(-8, 16)), random.Next(0, 16));
            string text = value.ToString(i % 2 == 0 ? "R" : "F" + random.Next(0, 12), CultureInfo.InvariantCulture);
            Assert.True(General(text, out double expected));
            Assert.True(NumParse.TryParse(text, out double parsed), text);
            Assert.True(BitConverter.DoubleToInt64Bits(expected) == BitConverter.DoubleToInt64Bits(parsed), text);
            shortForm += NumParse.TryParseShort(text, out _) ? 1 : 0;
        }
        Assert.True(shortForm > 100_000, $"only {shortForm} texts took the short form");
    }
}
