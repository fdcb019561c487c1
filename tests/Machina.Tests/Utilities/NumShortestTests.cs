using System.Globalization;

namespace Machina.Tests.Utilities;

/// <summary>The fast lossless (R) and 15-digit (G15) writers print exactly what .NET's general formatting prints.</summary>
public class NumShortestTests
{
    private static string R(double value) => (value == 0 ? 0 : value).ToString("R", CultureInfo.InvariantCulture);

    private static string G15(double value) => (value == 0 ? 0 : value).ToString("G15", CultureInfo.InvariantCulture);

    private static string Fast(double value, bool general)
    {
        Span<char> buffer = stackalloc char[NumAppend.MaxChars];
        int n = general ? NumShortest.WriteGeneral(buffer, value) : NumShortest.WriteRoundTrip(buffer, value);
        return new string(buffer[..n]);
    }

    private static IEnumerable<double> Values(int seed)
    {
        double[] edges = [0, -0.0, 1, -1, 0.1, 0.2, 0.3, 1.0 / 3, 2.0 / 3, 0.1 + 0.2, 0.0001, 0.00009999, 0.00011, 1e-5, 99999999999999.9,
                          1e13, 99999999999999, 1e14, 123456789012345, 1e15, 1e16, 4.35, 2.675, 1.005, 9.9999999999999995, 0.999999999999999,
                          double.Epsilon, double.MaxValue, double.MinValue, double.NaN, double.PositiveInfinity, double.NegativeInfinity];
        foreach (double edge in edges)
        {
            yield return edge;
            yield return -edge;
        }
        var random = new Random(seed);
        for (int i = 0; i < 100_000; i++)
        {
            double scale = Math.Pow(10, random.Next(-6, 16));
            yield return Math.Round((random.NextDouble() - 0.5) * scale, random.Next(0, 12));
            yield return (random.NextDouble() - 0.5) * scale;
            yield return Math.Round((random.NextDouble() - 0.5) * 20, 3) + Math.Round((random.NextDouble() - 0.5) * 20, 3);
        }
    }

    [Fact]
    public void WriteRoundTrip_RandomAndEdgeValues_SameTextAsR()
    {
        int fast = 0;
        Span<char> buffer = stackalloc char[NumAppend.MaxChars];
        foreach (double value in Values(21))
        {
            Assert.Equal(R(value), Fast(value, general: false));
            fast += NumShortest.TryWrite(buffer, value) >= 0 ? 1 : 0;
        }
        // The fast path must actually be taken for the numbers of toolpaths (not only the fallback tested).
        Assert.True(fast > 110_000, $"only {fast} values took the fast path");
    }

    [Fact]
    public void WriteRoundTrip_AroundTheThreeDecimalProbe_SameTextAsRAndG15()
    {
        // The probe at 3 decimals decides for numbers up to 10^12 with up to 3 decimals, and sends the others to the
        // search: numbers on both sides of 10^12 (where the probe's scaled value reaches 10^15), with 0 to 6 decimals.
        var random = new Random(23);
        int probed = 0;
        for (int i = 0; i < 200_000; i++)
        {
            int decimals = random.Next(0, 7);
            double size = Math.Pow(10, random.Next(-3, 15)) * (1 + random.NextDouble() * 9);
            double value = Math.Round(size, decimals) * (random.Next(2) == 0 ? 1 : -1);
            Assert.Equal(R(value), Fast(value, general: false));
            Assert.Equal(G15(value), Fast(value, general: true));
            probed += decimals <= 3 && Math.Abs(value) < 1e12 ? 1 : 0;
        }
        Assert.True(probed > 50_000, $"only {probed} values were of the probe's kind");
    }

    [Fact]
    public void WriteGeneral_RandomAndEdgeValues_SameTextAsG15()
    {
        foreach (double value in Values(22))
        {
            Assert.Equal(G15(value), Fast(value, general: true));
        }
    }

    [Theory]
    [InlineData(4.158, "4.158")]
    [InlineData(-0.63, "-0.63")]
    [InlineData(0.0001, "0.0001")]
    [InlineData(0.00001, null)]
    [InlineData(-0.0, "0")]
    [InlineData(1e14, null)]
    [InlineData(0.1234567891, null)]
    public void TryWrite_Value_WritesPlainTextOrDeclines(double value, string? expected)
    {
        Span<char> buffer = stackalloc char[NumAppend.MaxChars];
        int n = NumShortest.TryWrite(buffer, value);
        Assert.Equal(expected, n < 0 ? null : new string(buffer[..n]));
    }

    [Fact]
    public void AppendGeneral_NegativeZeroAndFraction_AsG15()
    {
        Assert.Equal("0|-2.5|1E-05", new System.Text.StringBuilder().AppendGeneral(-0.0).Append('|').AppendGeneral(-2.5).Append('|').AppendGeneral(0.00001).ToString());
    }
}
