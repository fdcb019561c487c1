using Machina.Tests.Geometry;

namespace Machina.Tests.Utilities;

public class NumTests
{
    [Fact]
    public void G_FifteenDigits_HidesBinaryNoise()
    {
        Assert.Equal("15.6", Num.G(1.5 * 10.4));
        Assert.Equal("0.3", Num.G(0.1 + 0.2));
        Assert.Equal("1E+20", Num.G(1e20));
        Assert.Equal("0", Num.G(-0.0));
        Assert.Equal("-2.5", Num.G(-2.5));
    }

    [Theory]
    [InlineData(2.5, 0, "2")]
    [InlineData(3.5, 0, "4")]
    [InlineData(-2.5, 0, "-2")]
    [InlineData(0.125, 2, "0.12")]
    [InlineData(0.375, 2, "0.38")]
    [InlineData(1.23456, 3, "1.235")]
    [InlineData(-0.0004, 3, "0")]
    [InlineData(-0.0, 3, "0")]
    [InlineData(100, 3, "100")]
    [InlineData(0.70710678, 4, "0.7071")]
    public void F_Rounding_BankersAndShortest(double value, int decimals, string expected)
    {
        Assert.Equal(expected, Num.F(value, decimals));
    }

    [Theory]
    [InlineData(0.1)]
    [InlineData(1.0 / 3)]
    [InlineData(Math.PI)]
    [InlineData(1e-300)]
    [InlineData(-123456.789012345678)]
    [InlineData(double.MaxValue)]
    [InlineData(double.Epsilon)]
    public void R_AnyDouble_ParsesBackExactly(double value)
    {
        string text = Num.R(value);
        Assert.Equal(value, double.Parse(text, System.Globalization.CultureInfo.InvariantCulture));
    }

    [Fact]
    public void R_NegativeZero_PrintedAsZero()
    {
        Assert.Equal("0", Num.R(-0.0));
        Assert.Equal("0", Num.I(0));
        Assert.Equal("-42", Num.I(-42));
    }

    [Fact]
    public void Formatting_GermanCulture_InvariantDecimalPoint()
    {
        string text = Oracle.UnderGerman(() => Num.G(1234.5) + "|" + Num.F(1.25, 1) + "|" + Num.R(0.1) + "|" + Num.I(1234567));
        Assert.Equal("1234.5|1.2|0.1|1234567", text);
    }

    [Fact]
    public void Finite_NaNOrInfinity_ThrowsNamingParameter()
    {
        Assert.Equal(3.5, Num.Finite(3.5, "speed"));
        var ex = Assert.Throws<ArgumentException>(() => Num.Finite(double.NaN, "speed"));
        Assert.Equal("speed", ex.ParamName);
        Assert.Contains("NaN", ex.Message);
        Assert.Throws<ArgumentException>(() => Num.Finite(double.NegativeInfinity, "speed"));
    }
}
