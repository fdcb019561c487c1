using System.Globalization;

namespace Machina.Tests.Utilities;

/// <summary>The one writer of numbers in programs: fixed decimals, plain notation at every size, never a number that is not finite.</summary>
public class NumAppendFormatTests
{
    [Theory]
    [InlineData(0, 3, "0")]
    [InlineData(-0.0004, 3, "0")]
    [InlineData(-0.0006, 3, "-0.001")]
    [InlineData(12.5, 0, "12")]
    [InlineData(13.5, 0, "14")]
    [InlineData(0.00001, 5, "0.00001")]
    [InlineData(0.000001, 6, "0.000001")]
    [InlineData(-1234.5, 3, "-1234.5")]
    [InlineData(100, 3, "100")]
    [InlineData(1e20, 3, "100000000000000000000")]
    [InlineData(-1e20, 6, "-100000000000000000000")]
    [InlineData(1234567890123.25, 6, "1234567890123.25")]
    public void Format_Values_FixedPointText(double value, int decimals, string expected) =>
        Assert.Equal(expected, NumAppend.Format(value, decimals));

    /// <summary>
    /// The builder's path (RAPID and URScript) and the string's path (KRL and G-code) write a huge value the same way, in
    /// plain digits: the builder's used to write "1E+20", which G-code cannot read and KRL's writer never wrote.
    /// </summary>
    [Theory]
    [InlineData(1e20, 6)]
    [InlineData(-3.5e16, 3)]
    [InlineData(9.99e14, 1)]
    public void AppendFixed_HugeValue_PlainDigitsAsFormat(double value, int decimals)
    {
        string text = new System.Text.StringBuilder().AppendFixed(value, decimals).ToString();
        Assert.Equal(NumAppend.Format(value, decimals), text);
        Assert.DoesNotContain("E", text, StringComparison.Ordinal);
        Assert.Equal(value, double.Parse(text, CultureInfo.InvariantCulture), Math.Abs(value) * 1e-15);
    }

    [Theory]
    [InlineData(double.NaN)]
    [InlineData(double.PositiveInfinity)]
    [InlineData(double.NegativeInfinity)]
    public void AppendFixed_NotFinite_RefusedNotWritten(double value)
    {
        var sb = new System.Text.StringBuilder("X");
        Assert.Throws<ArgumentOutOfRangeException>(() => sb.AppendFixed(value, 3));
        Assert.Equal("X", sb.ToString());
    }

    [Fact]
    public void Format_ManyValues_SameTextAsNumF()
    {
        var random = new Random(3);
        for (int i = 0; i < 20000; i++)
        {
            double value = (random.NextDouble() - 0.5) * Math.Pow(10, random.Next(-2, 7));
            int decimals = random.Next(0, 5);
            Assert.Equal(Num.F(value, decimals), NumAppend.Format(value, decimals));
        }
    }

    [Fact]
    public void Format_GermanCulture_StillAPoint()
    {
        CultureInfo saved = CultureInfo.CurrentCulture;
        try
        {
            CultureInfo.CurrentCulture = new CultureInfo("de-DE");
            Assert.Equal("-3.25", NumAppend.Format(-3.25, 3));
        }
        finally
        {
            CultureInfo.CurrentCulture = saved;
        }
    }
}
