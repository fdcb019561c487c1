namespace Machina.Tests.Geometry;

public class ConversionTests
{
    [Fact]
    public void RotationVector_ToRotation_AxisTimesAngle()
    {
        Rotation r = new RotationVector(0, 90, 0).ToRotation();
        Oracle.SameRotation(Rotation.FromAxisAngle(Vector.YAxis, 90), r, 1e-12);
        Assert.Equal(90, new RotationVector(0, 90, 0).Angle);
        Assert.Equal(13, new RotationVector(3, 4, 12).Angle);
        Assert.Equal(Rotation.Identity, new RotationVector(0, 0, 0).ToRotation());
    }

    [Fact]
    public void RotationVector_ToRadians_ScalesEachComponent()
    {
        Vector v = new RotationVector(180, -90, 45).ToRadians();
        Assert.Equal(Math.PI, v.X, 15);
        Assert.Equal(-Math.PI / 2, v.Y, 15);
        Assert.Equal(Math.PI / 4, v.Z, 15);
        Assert.Equal("RotationVector[180, -90, 45]", new RotationVector(180, -90, 45).ToString());
    }

    [Theory]
    [InlineData(1, 0, 0, 180)]
    [InlineData(1, 1, 0, 180)]
    [InlineData(0, -2, 1, 180)]
    [InlineData(1, 2, 3, 0.001)]
    [InlineData(1, 2, 3, 1e-9)]
    [InlineData(-4, 1, 0, 123)]
    public void RotationVector_RoundTrip_SameRotationAndLengthIsAngle(double x, double y, double z, double deg)
    {
        Rotation r = Rotation.FromAxisAngle(x, y, z, deg);
        RotationVector rv = r.ToRotationVector();
        Assert.Equal(deg, rv.Angle, 9);
        Oracle.SameRotation(r, rv.ToRotation(), 1e-9);
        Vector dir = new Vector(x, y, z).Normalized();
        Assert.Equal(1, Math.Abs(Vector.Dot(dir, new Vector(rv.X, rv.Y, rv.Z) / rv.Angle)), 9);
    }

    [Fact]
    public void RotationVector_TinyAngle_KeepsAxis()
    {
        RotationVector rv = Rotation.FromAxisAngle(Vector.ZAxis, 1e-9).ToRotationVector();
        Assert.Equal(0, rv.X);
        Assert.Equal(0, rv.Y);
        Assert.Equal(1e-9, rv.Z, 1e-20);
        Rotation back = Rotation.FromRotationVector(new Vector(0, 0, 1e-9));
        Assert.Equal(1e-9, back.AngleTo(Rotation.Identity), 1e-20);
    }

    [Fact]
    public void RotationVector_NonFinite_ThrowsArgumentException()
    {
        Assert.Throws<ArgumentException>(() => new RotationVector(double.NaN, 0, 0).ToRotation());
    }

    [Fact]
    public void AxisAngle_ToRotation_NonUnitAxisAndZeroCases()
    {
        Oracle.SameRotation(Rotation.FromAxisAngle(Vector.XAxis, 30), new AxisAngle(new Vector(5, 0, 0), 30).ToRotation(), 1e-12);
        Assert.Equal(Rotation.Identity, new AxisAngle(Vector.Zero, 45).ToRotation());
        Assert.Equal(Rotation.Identity, new AxisAngle(Vector.ZAxis, 0).ToRotation());
        Assert.Equal(Rotation.Identity, default(AxisAngle).ToRotation());
        Assert.Equal("AxisAngle[0, 1, 0, 90]", new AxisAngle(Vector.YAxis, 90).ToString());
    }

    [Fact]
    public void AxisAngle_ShortButNonZeroAxis_StillRotates()
    {
        Oracle.SameRotation(Rotation.FromAxisAngle(Vector.XAxis, 90), new AxisAngle(new Vector(1e-7, 0, 0), 90).ToRotation(), 1e-9);
        Assert.Throws<ArgumentException>(() => new AxisAngle(new Vector(1e-12, 0, 0), 90).ToRotation());
        Assert.Throws<ArgumentException>(() => new AxisAngle(Vector.XAxis, double.NaN).ToRotation());
    }

    [Fact]
    public void RotationVector_FullTurn_IsIdentity()
    {
        Rotation r = new RotationVector(0, 0, 360).ToRotation();
        Oracle.SameRotation(Rotation.Identity, r, 1e-12);
        Assert.Equal(0, r.ToRotationVector().Angle, 12);
        Oracle.SameRotation(Rotation.FromAxisAngle(Vector.ZAxis, -90), new RotationVector(0, 0, 270).ToRotation(), 1e-12);
    }

    [Fact]
    public void AxisAngle_NegativeAndLargeAngles_SameRotationAsEquivalent()
    {
        Oracle.SameRotation(new AxisAngle(-Vector.ZAxis, 90).ToRotation(), new AxisAngle(Vector.ZAxis, -90).ToRotation(), 1e-12);
        Oracle.SameRotation(new AxisAngle(Vector.ZAxis, 450).ToRotation(), new AxisAngle(Vector.ZAxis, 90).ToRotation(), 1e-12);
        Oracle.SameRotation(new AxisAngle(Vector.ZAxis, 270).ToRotation(), new AxisAngle(Vector.ZAxis, -90).ToRotation(), 1e-12);
    }

    [Fact]
    public void Matrix_FromRows_NonOrthogonal_Orthonormalised()
    {
        RotationMatrix m = RotationMatrix.FromRows(2, 1, 0, 0, 3, 0, 0, 0, 7);
        Assert.Equal(Vector.XAxis, m.XAxis);
        Oracle.SameVector(Vector.YAxis, m.YAxis, 1e-15);
        Oracle.SameVector(Vector.ZAxis, m.ZAxis, 1e-15);
        Assert.Equal("RotationMatrix[[1, 0, 0], [0, 1, 0], [0, 0, 1]]", m.ToString());
        Assert.Throws<ArgumentException>(() => RotationMatrix.FromRows(1, 2, 0, 0, 0, 0, 0, 0, 0));
        Assert.Throws<ArgumentException>(() => RotationMatrix.FromRows(0, 0, 0, 0, 0, 0, 0, 0, 0));
    }

    [Fact]
    public void Matrix_HandDerivedZ90_RowMajorEntries()
    {
        RotationMatrix m = Rotation.FromAxisAngle(Vector.ZAxis, 90).ToMatrix();
        Assert.Equal(0, m.M00, 15); Assert.Equal(-1, m.M01, 15); Assert.Equal(0, m.M02, 15);
        Assert.Equal(1, m.M10, 15); Assert.Equal(0, m.M11, 15); Assert.Equal(0, m.M12, 15);
        Assert.Equal(0, m.M20, 15); Assert.Equal(0, m.M21, 15); Assert.Equal(1, m.M22, 15);
    }

    public static TheoryData<double, double, double, double> ShepperdCases => new()
    {
        { 0, 0, 1, 10 },    // trace > 0
        { 1, 0.1, 0.1, 170 }, // M00 largest
        { 0.1, 1, -0.1, 170 }, // M11 largest
        { -0.1, 0.1, 1, 170 }, // M22 largest
        { 1, 1, 1, 180 },    // tie on the diagonal
        { 1, 0, 0, 180 }, { 0, 1, 0, 180 }, { 0, 0, 1, 180 },
        { 1, 2, 3, 1e-9 },
    };

    [Theory]
    [MemberData(nameof(ShepperdCases))]
    public void Matrix_ToRotation_EveryShepperdBranch_RoundTrips(double x, double y, double z, double deg)
    {
        Rotation r = Rotation.FromAxisAngle(x, y, z, deg);
        RotationMatrix m = r.ToMatrix();
        Rotation back = m.ToRotation();
        Oracle.SameRotation(r, back, 1e-10);
        Assert.Equal(m.M00, back.ToMatrix().M00, 14);
        Assert.Equal(m.M12, back.ToMatrix().M12, 14);
        Assert.Equal(m.M21, back.ToMatrix().M21, 14);
    }

    [Fact]
    public void Matrix_ToYawPitchRoll_SameAsRotation()
    {
        Rotation r = Rotation.FromYawPitchRoll(12, -34, 56);
        Assert.Equal(r.ToYawPitchRoll(), r.ToMatrix().ToYawPitchRoll());
        Assert.Equal(-34, r.ToMatrix().ToYawPitchRoll().Pitch, 10);
    }
}
