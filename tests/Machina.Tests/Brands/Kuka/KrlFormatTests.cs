namespace Machina.Tests.Brands.Kuka;

public class KrlFormatTests
{
    // Rz(a)·Ry(b)·Rx(c) written out by hand: KUKA's definition of A, B, C (degrees).
    private static double[,] MatrixFromAbc(double a, double b, double c)
    {
        double ca = Math.Cos(a * Math.PI / 180), sa = Math.Sin(a * Math.PI / 180);
        double cb = Math.Cos(b * Math.PI / 180), sb = Math.Sin(b * Math.PI / 180);
        double cc = Math.Cos(c * Math.PI / 180), sc = Math.Sin(c * Math.PI / 180);
        return new[,]
        {
            { ca * cb, ca * sb * sc - sa * cc, ca * sb * cc + sa * sc },
            { sa * cb, sa * sb * sc + ca * cc, sa * sb * cc - ca * sc },
            { -sb, cb * sc, cb * cc },
        };
    }

    private static void AssertSameFrame(Rotation rotation, double a, double b, double c)
    {
        double[,] m = MatrixFromAbc(a, b, c);
        Vector x = rotation.XAxis, y = rotation.YAxis, z = rotation.ZAxis;
        double[,] r = { { x.X, y.X, z.X }, { x.Y, y.Y, z.Y }, { x.Z, y.Z, z.Z } };
        for (int i = 0; i < 3; i++)
        {
            for (int j = 0; j < 3; j++)
            {
                Assert.Equal(m[i, j], r[i, j], 9);
            }
        }
    }

    [Fact]
    public void Abc_DefaultDownwardTool_IsA180B0C180()
    {
        // Machina's default: half a turn about Y, tool Z pointing down, tool X along world -X.
        (double a, double b, double c) = KrlFormat.Abc(Rotation.FlippedAroundY);

        Assert.Equal(180, Math.Abs(a), 9);
        Assert.Equal(0, b, 9);
        Assert.Equal(180, Math.Abs(c), 9);
        // Same frame as the spec's "A 0, B 180, C 0" written with B in [-90, 90].
        AssertSameFrame(Rotation.FlippedAroundY, 0, 180, 0);
        Assert.Equal("180", KrlFormat.Angle(a));
        Assert.Equal("180", KrlFormat.Angle(c));
    }

    [Fact]
    public void Abc_NinetyDegreesAboutZ_IsA90B0C0()
    {
        (double a, double b, double c) = KrlFormat.Abc(Rotation.FromAxisAngle(0, 0, 1, 90));

        Assert.Equal(90, a, 9);
        Assert.Equal(0, b, 9);
        Assert.Equal(0, c, 9);
    }

    [Fact]
    public void Abc_CompoundRotation_GivesTheAnglesItWasBuiltFrom()
    {
        // Built from plain axis-angle turns, not from Euler angles: Z by 30, then the new Y by 20, then the new X by 10.
        Rotation r = Rotation.FromAxisAngle(0, 0, 1, 30) * Rotation.FromAxisAngle(0, 1, 0, 20) * Rotation.FromAxisAngle(1, 0, 0, 10);

        (double a, double b, double c) = KrlFormat.Abc(r);

        Assert.Equal(30, a, 9);
        Assert.Equal(20, b, 9);
        Assert.Equal(10, c, 9);
        AssertSameFrame(r, a, b, c);
    }

    [Fact]
    public void Abc_ToolPointingAlongWorldX_IsB90()
    {
        // Hello Robot's Rotate(0,1,0,-90) from the default: the tool Z axis points to world +X.
        Rotation r = Rotation.FromAxisAngle(0, 1, 0, -90) * Rotation.FlippedAroundY;
        Assert.True(r.ZAxis.IsSimilar(new Vector(1, 0, 0)));

        (double a, double b, double c) = KrlFormat.Abc(r);

        Assert.Equal(90, b, 9);
        AssertSameFrame(r, a, b, c);
    }

    [Fact]
    public void Abc_ManyRandomRotations_RebuildTheSameFrame()
    {
        var random = new Random(7);
        for (int i = 0; i < 200; i++)
        {
            var axis = new Vector(random.NextDouble() - 0.5, random.NextDouble() - 0.5, random.NextDouble() - 0.5);
            Rotation r = Rotation.FromAxisAngle(axis, random.NextDouble() * 360 - 180);
            (double a, double b, double c) = KrlFormat.Abc(r);
            Assert.InRange(b, -90, 90);
            AssertSameFrame(r, a, b, c);
        }
    }

    [Theory]
    [InlineData(0.1, "0.1")]
    [InlineData(-0.0001, "0")]
    [InlineData(1234.56789, "1234.568")]
    [InlineData(0.0005, "0")]
    [InlineData(0.0015, "0.002")]
    public void Mm_Values_ThreeDecimalsNoMinusZero(double value, string expected) => Assert.Equal(expected, KrlFormat.Mm(value));

    [Fact]
    public void Fine_TinyValue_IsFixedPointNotExponent()
    {
        Assert.Equal("0.000001", KrlFormat.Fine(0.000001));
        Assert.Equal("0.000002", KrlFormat.SpeedMetresPerSecond(0.002));
        Assert.Equal("2.5", KrlFormat.AccelerationMetresPerSecond2(2500));
        Assert.Equal("1.5", KrlFormat.Seconds(1500));
    }

    [Theory]
    [InlineData("HelloRobot", "HelloRobot")]
    [InlineData("LIN", "M_LIN")]
    [InlineData("end", "M_end")]
    [InlineData("AVeryLongProgramNameForAKukaRobot", "AVeryLongProgramNameForA")]
    [InlineData("", "Machina")]
    public void ModuleName_Names_AreValidKrlNames(string programName, string expected)
    {
        string name = KrlText.ModuleName(programName);

        Assert.Equal(expected, name);
        Assert.True(KrlText.IsValidName(name));
    }

    [Fact]
    public void Comment_LineBreaks_BecomeSpaces() => Assert.Equal("a  b c", KrlText.Comment("a\r\nb\tc"));
}
