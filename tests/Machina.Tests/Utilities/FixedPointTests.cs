using System.Globalization;

namespace Machina.Tests.Utilities;

public class FixedPointTests
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
    public void Format_Values_FixedPointText(double value, int decimals, string expected) =>
        Assert.Equal(expected, FixedPoint.Format(value, decimals));

    [Fact]
    public void Format_ManyValues_SameTextAsNumF()
    {
        var random = new Random(3);
        for (int i = 0; i < 20000; i++)
        {
            double value = (random.NextDouble() - 0.5) * Math.Pow(10, random.Next(-2, 7));
            int decimals = random.Next(0, 5);
            Assert.Equal(Num.F(value, decimals), FixedPoint.Format(value, decimals));
        }
    }

    [Fact]
    public void Format_GermanCulture_StillAPoint()
    {
        CultureInfo saved = CultureInfo.CurrentCulture;
        try
        {
            CultureInfo.CurrentCulture = new CultureInfo("de-DE");
            Assert.Equal("-3.25", FixedPoint.Format(-3.25, 3));
        }
        finally
        {
            CultureInfo.CurrentCulture = saved;
        }
    }
}
