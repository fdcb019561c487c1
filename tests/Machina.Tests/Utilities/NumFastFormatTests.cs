using System.Globalization;
using System.Text;

namespace Machina.Tests.Utilities;

/// <summary>
/// The allocation-free number writers must print exactly what the general formatting printed before them: the compilers'
/// golden files depend on every digit.
/// </summary>
public class NumFastFormatTests
{
    private static string Reference(double value, int decimals)
    {
        double rounded = Math.Round(value, decimals);
        return (rounded == 0 ? 0 : rounded).ToString("G15", CultureInfo.InvariantCulture);
    }

    private static IEnumerable<double> Values(int seed)
    {
        var random = new Random(seed);
        double[] edges = [0, -0.0, 1, -1, 0.5, -0.5, 0.0005, -0.0005, 0.00005, 1e-4, 1e-5, 0.00015, 123456789012.345, 999999999999.9995,
                          1e14, 1e15, 1e16, -1e15, 1e300, double.Epsilon, double.MaxValue, double.NaN, double.PositiveInfinity, double.NegativeInfinity];
        foreach (double edge in edges)
        {
            yield return edge;
        }
        for (int i = 0; i < 20_000; i++)
        {
            // Mostly the decimals a toolpath has, some tiny and some huge magnitudes.
            double scale = Math.Pow(10, random.Next(-9, 17));
            yield return Math.Round((random.NextDouble() - 0.5) * scale, random.Next(0, 10));
            yield return (random.NextDouble() - 0.5) * scale;
        }
    }

    [Fact]
    public void F_RandomAndEdgeValues_SameTextAsGeneralFormatting()
    {
        int checkedCount = 0;
        foreach (double value in Values(11))
        {
            for (int decimals = 0; decimals <= 9; decimals++)
            {
                Assert.Equal(Reference(value, decimals), Num.F(value, decimals));
                checkedCount++;
            }
        }
        Assert.Equal((24 + 40_000) * 10, checkedCount);
    }

    [Theory]
    [InlineData(0.00001, 5, "1E-05")]
    [InlineData(0.0001, 5, "0.0001")]
    [InlineData(-0.0004, 3, "0")]
    [InlineData(-0.0006, 3, "-0.001")]
    [InlineData(2.5, 0, "2")]
    [InlineData(1234.5678, 3, "1234.568")]
    public void F_KnownValues_ExactText(double value, int decimals, string expected) => Assert.Equal(expected, Num.F(value, decimals));

    [Fact]
    public void AppendFixed_SmallValues_PlainDecimalNotation()
    {
        Assert.Equal("0.00001", new StringBuilder().AppendFixed(0.00001, 6).ToString());
        Assert.Equal("-12.5", new StringBuilder().AppendFixed(-12.5, 6).ToString());
        // Plain digits at every size (one policy for every language; G-code reads no exponent): 1 and 300 zeros.
        Assert.Equal("1" + new string('0', 300), new StringBuilder().AppendFixed(1e300, 3).ToString());
    }

    [Fact]
    public void VectorText_UsesThreeDecimals_InBothForms()
    {
        var v = new Vector(7.2164, -0.0004, 1e-5);
        Assert.Equal("[7.216, 0, 0]", v.ToString());
        Assert.Equal("[7.216,0,0]", v.ToArrayString());
        Assert.Equal("Move [1.5, -2, 3.001] mm", new ActionTranslation(new Vector(1.5, -2, 3.0006), true).Describe());
        Assert.Equal("Move to [300, 0, 500] mm", new ActionTranslation(new Vector(300, 0, 500), false).Describe());
    }
}
