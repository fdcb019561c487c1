using System.Globalization;
using System.Text;

namespace Machina.Tests.Brands.Abb;

/// <summary>
/// A request's numbers are written without the general formatter when they are short decimals (a move's millimetres to 3 places, its
/// quaternion to 4): the text must be G15's, byte for byte, for every such value, and every other value must still go to G15.
/// </summary>
public class AbbNumberTextTests
{
    [Fact]
    public void ShortDecimals_AreWrittenAsG15WritesThem()
    {
        var random = new Random(4553);
        Span<byte> buffer = stackalloc byte[64];
        int fast = 0;
        for (int i = 0; i < 300_000; i++)
        {
            int places = random.Next(0, 5);
            double scale = Math.Pow(10, random.Next(0, 11));
            double raw = (random.NextDouble() * 2 - 1) * scale;
            double value = (i % 3) switch
            {
                0 => Math.Round(raw, places),
                1 => Math.Round(raw / 1000, places),
                _ => Math.Round(random.NextDouble() * 2 - 1, 4),        // a quaternion's component
            };
            fast += Same(value, buffer) ? 1 : 0;
        }
        Assert.True(fast > 290_000, $"only {fast} values took the short way");
    }

    [Fact]
    public void OtherValues_GoToG15()
    {
        var random = new Random(4554);
        Span<byte> buffer = stackalloc byte[64];
        double[] edges = [0, -0.0, 1e-5, -1e-5, 0.0001, -0.0001, 0.00005, 9_999_999_999.9999, 1e10, -1e10, 12345678.12345, 0.1 + 0.2,
            double.Epsilon, double.MaxValue, double.NaN, double.PositiveInfinity, double.NegativeInfinity, 1e15, 123456789012.5];
        foreach (double value in edges)
        {
            Same(value, buffer);
        }
        for (int i = 0; i < 100_000; i++)
        {
            Same(BitConverter.Int64BitsToDouble(random.NextInt64()), buffer);
            Same((random.NextDouble() * 2 - 1) * Math.Pow(10, random.Next(-6, 16)), buffer);
        }
    }

    [Fact]
    public void AMove_IsWrittenAsBefore() =>
        Assert.Equal("@7 1 -302.5 0.001 1000.123 0.7071 -0.7071 0 0.0001;",
            AbbRequest.Move(7, true, new Vector(-302.5, 0.0012, 1000.1234), Rotation.FromQuaternion(0.70710678, -0.70710678, 0, 0.0001)).ToWireText());

    /// <summary>Writes <paramref name="value"/> as a request does and compares with G15; true when the short way was taken.</summary>
    private static bool Same(double value, Span<byte> buffer)
    {
        string want = value == AbbRequest.UnusedAxis ? "9E9" : (value == 0 ? 0 : value).ToString("G15", CultureInfo.InvariantCulture);
        int n = AbbRequest.FormatNumber(value, buffer);
        Assert.Equal(want, Encoding.ASCII.GetString(buffer[..n]));
        bool fast = AbbRequest.TryWriteShortDecimal(value, buffer, out int m);
        if (fast)
        {
            Assert.Equal(want, Encoding.ASCII.GetString(buffer[..m]));
        }
        return fast;
    }
}
