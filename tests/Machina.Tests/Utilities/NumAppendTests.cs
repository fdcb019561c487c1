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
    [InlineData(1e20, 3, "1E+20")]
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
}
