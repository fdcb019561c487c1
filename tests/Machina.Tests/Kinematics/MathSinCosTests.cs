namespace Machina.Tests.Kinematics;

/// <summary>
/// The solvers and forward kinematics take an angle's sine and cosine with one <see cref="Math.SinCos"/> (issue 45): on every
/// platform the tests run on it must give the bits of <see cref="Math.Sin"/> and <see cref="Math.Cos"/>, and the UR solver's
/// shortcuts (sin(−x) = −sin(x), cos(−x) = cos(x), atan2(−y, x) = −atan2(y, x)) must hold to the bit, or a solution would move.
/// </summary>
public class MathSinCosTests
{
    [Fact]
    public void SinCos_IsSinAndCos_AndTheSignShortcutsHold_BitForBit()
    {
        var random = new Random(4549);
        for (int i = 0; i < 1_000_000; i++)
        {
            // Angles of every size the solvers meet (|x| up to a few turns), near zero, and beyond.
            double x = (random.NextDouble() * 2 - 1) * (i % 4) switch { 0 => 4 * Math.PI, 1 => 1e-3, 2 => Math.PI, _ => 1e4 };
            (double s, double c) = Math.SinCos(x);
            Assert.Equal(Bits(Math.Sin(x)), Bits(s));
            Assert.Equal(Bits(Math.Cos(x)), Bits(c));
            Assert.Equal(Bits(-Math.Sin(x)), Bits(Math.Sin(-x)));
            Assert.Equal(Bits(Math.Cos(x)), Bits(Math.Cos(-x)));
            double y = (random.NextDouble() * 2 - 1) * 1000, z = (random.NextDouble() * 2 - 1) * 1000;
            Assert.Equal(Bits(-Math.Atan2(y, z)), Bits(Math.Atan2(-y, z)));
        }
        foreach (double x in (double[])[0.0, -0.0, Math.PI, -Math.PI, Math.PI / 2, -Math.PI / 2, double.Epsilon, 1e-300])
        {
            (double s, double c) = Math.SinCos(x);
            Assert.Equal(Bits(Math.Sin(x)), Bits(s));
            Assert.Equal(Bits(Math.Cos(x)), Bits(c));
        }
        Assert.Equal(Bits(-Math.Atan2(0.0, -1.0)), Bits(Math.Atan2(-0.0, -1.0)));
    }

    private static long Bits(double x) => BitConverter.DoubleToInt64Bits(x);
}
