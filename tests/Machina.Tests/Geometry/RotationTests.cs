using SN = System.Numerics;

namespace Machina.Tests.Geometry;

public class RotationTests
{
    private static readonly double S = Math.Sqrt(0.5);

    public static TheoryData<double, double, double, double> AxisAngles => new()
    {
        { 1, 0, 0, 90 }, { 0, 1, 0, -30 }, { 0, 0, 1, 180 }, { 1, 2, 3, 47.5 }, { -0.3, 0.1, 2, 270 },
        { 5, -5, 1, 179.9 }, { 0, 0, 3, 360 }, { 1, 1, 1, 720.5 }, { 0.2, -0.7, 0.1, 1e-3 },
    };

    [Theory]
    [MemberData(nameof(AxisAngles))]
    public void FromAxisAngle_AnyAxis_MatchesNumerics(double x, double y, double z, double degrees)
    {
        Rotation r = Rotation.FromAxisAngle(x, y, z, degrees);
        Oracle.SameQuaternion(Oracle.Axis(x, y, z, degrees), r);
        Assert.Equal(1, r.W * r.W + r.X * r.X + r.Y * r.Y + r.Z * r.Z, 15);
    }

    [Fact]
    public void FromAxisAngle_HandDerived_ExactHalfAngles()
    {
        Rotation r = Rotation.FromAxisAngle(Vector.ZAxis, 90);
        Assert.Equal(S, r.W, 15);
        Assert.Equal(0, r.X);
        Assert.Equal(0, r.Y);
        Assert.Equal(S, r.Z, 15);
        Assert.Equal(Rotation.Identity, Rotation.FromAxisAngle(Vector.Zero, 0));
        Assert.Equal("[0.7071, 0, 0, 0.7071]", r.ToQuaternionString());
    }

    [Fact]
    public void FromAxisAngle_ZeroOrNonFiniteAxis_ThrowsArgumentException()
    {
        Assert.Throws<ArgumentException>(() => Rotation.FromAxisAngle(Vector.Zero, 90));
        Assert.Throws<ArgumentException>(() => Rotation.FromAxisAngle(new Vector(double.NaN, 0, 1), 90));
        Assert.Throws<ArgumentException>(() => Rotation.FromAxisAngle(Vector.ZAxis, double.PositiveInfinity));
        Assert.Throws<ArgumentException>(() => Rotation.FromAxisAngle(Vector.ZAxis, double.NaN));
    }

    [Fact]
    public void FromQuaternion_NonNormalised_ScaledToUnit()
    {
        Rotation r = Rotation.FromQuaternion(2, 0, 0, 2);
        Assert.Equal(S, r.W, 15);
        Assert.Equal(S, r.Z, 15);
        Rotation small = Rotation.FromQuaternion(1e-6, 1e-6, 0, 0);
        Assert.Equal(S, small.W, 15);
        Assert.Equal(S, small.X, 15);
        Oracle.SameRotation(Rotation.FromAxisAngle(Vector.XAxis, 90), small);
    }

    [Theory]
    [InlineData(0, 0, 0, 0)]
    [InlineData(1e-12, 0, 0, 0)]
    [InlineData(double.NaN, 0, 0, 1)]
    [InlineData(1, double.PositiveInfinity, 0, 0)]
    [InlineData(1, 0, double.NegativeInfinity, 0)]
    public void FromQuaternion_ZeroOrNonFinite_ThrowsArgumentException(double w, double x, double y, double z)
    {
        Assert.Throws<ArgumentException>(() => Rotation.FromQuaternion(w, x, y, z));
    }

    [Fact]
    public void Default_IsIdentity_EqualsIdentity()
    {
        Rotation d = default;
        Assert.Equal(Rotation.Identity, d);
        Assert.Equal(1, d.W);
        Assert.Equal(Vector.XAxis, d.XAxis);
        Assert.Equal("Rotation[1, 0, 0, 0]", d.ToString());
    }

    [Fact]
    public void Multiply_Order_MatchesNumericsHamiltonProduct()
    {
        SN.Quaternion na = Oracle.Axis(0, 0, 1, 90), nb = Oracle.Axis(1, 0, 0, 90);
        Rotation a = Oracle.ToRotation(na), b = Oracle.ToRotation(nb);
        // Numerics: q1 * q2 is the Hamilton product; Concatenate(first, second) = second * first.
        Oracle.SameQuaternion(na * nb, a * b);
        Oracle.SameQuaternion(SN.Quaternion.Concatenate(nb, na), a * b);
        Oracle.SameQuaternion(nb * na, b * a);
    }

    [Fact]
    public void Multiply_ApplyRightOperandFirst_VectorChain()
    {
        Rotation a = Rotation.FromAxisAngle(Vector.ZAxis, 90), b = Rotation.FromAxisAngle(Vector.XAxis, 90);
        var v = new Vector(0, 1, 0);
        // b: Y → Z; then a (about Z) leaves Z alone.
        Oracle.SameVector(Vector.ZAxis, (a * b) * v);
        Oracle.SameVector(a * (b * v), (a * b) * v);
        // a: Y → −X; then b (about X) leaves −X alone.
        Oracle.SameVector(-Vector.XAxis, (b * a) * v);
    }

    [Fact]
    public void GlobalAndLocal_SpecExamples_Quaternions()
    {
        Rotation rz = Rotation.FromAxisAngle(Vector.ZAxis, 90), rx = Rotation.FromAxisAngle(Vector.XAxis, 90);
        Rotation g = Rotation.Global(rz, rx), l = Rotation.Local(rz, rx);
        Assert.Equal("[0.5, 0.5, -0.5, 0.5]", g.ToQuaternionString());
        Assert.Equal("[0.5, 0.5, 0.5, 0.5]", l.ToQuaternionString());
        Assert.Equal(l, Rotation.Combine(rz, rx));
    }

    [Theory]
    [MemberData(nameof(AxisAngles))]
    public void Rotate_Vectors_MatchesNumericsTransform(double x, double y, double z, double degrees)
    {
        SN.Quaternion nq = Oracle.Axis(x, y, z, degrees);
        Rotation r = Oracle.ToRotation(nq);
        foreach (var v in new[] { new SN.Vector3(1, 0, 0), new SN.Vector3(0.3f, -2, 5), new SN.Vector3(-7, 1, 0.25f) })
        {
            Oracle.SameVector(SN.Vector3.Transform(v, nq), r * new Vector(v.X, v.Y, v.Z), 1e-5);
        }
    }

    [Fact]
    public void Rotate_PreservesLengthAndInverseUndoes_Exactish()
    {
        Rotation r = Rotation.FromAxisAngle(new Vector(1, -2, 0.5), 123.4);
        var v = new Vector(10, -20, 30);
        Vector w = r * v;
        Assert.Equal(v.Length, w.Length, 12);
        Oracle.SameVector(v, r.Inverse() * w, 1e-12);
        Oracle.SameRotation(Rotation.Identity, r * r.Inverse(), 1e-12);
    }

    [Theory]
    [MemberData(nameof(AxisAngles))]
    public void ToMatrix_AnyRotation_MatchesTransposedNumericsMatrix(double x, double y, double z, double degrees)
    {
        SN.Quaternion nq = Oracle.Axis(x, y, z, degrees);
        RotationMatrix m = Oracle.ToRotation(nq).ToMatrix();
        // Numerics uses row vectors: its rows are the images of the axes, i.e. our columns.
        SN.Matrix4x4 n = SN.Matrix4x4.CreateFromQuaternion(nq);
        const double t = 1e-6;
        Assert.Equal(n.M11, m.M00, t); Assert.Equal(n.M21, m.M01, t); Assert.Equal(n.M31, m.M02, t);
        Assert.Equal(n.M12, m.M10, t); Assert.Equal(n.M22, m.M11, t); Assert.Equal(n.M32, m.M12, t);
        Assert.Equal(n.M13, m.M20, t); Assert.Equal(n.M23, m.M21, t); Assert.Equal(n.M33, m.M22, t);
    }

    [Fact]
    public void Axes_ColumnsAreImagesOfWorldAxes_Equal()
    {
        Rotation r = Rotation.FromAxisAngle(new Vector(3, 1, -2), 77);
        Oracle.SameVector(r * Vector.XAxis, r.XAxis, 1e-15);
        Oracle.SameVector(r * Vector.YAxis, r.YAxis, 1e-15);
        Oracle.SameVector(r * Vector.ZAxis, r.ZAxis, 1e-15);
    }

    [Fact]
    public void FlippedAroundY_SpecDefault_AxesAndText()
    {
        Rotation r = Rotation.FlippedAroundY;
        Assert.Equal("[0, 0, 1, 0]", r.ToQuaternionString());
        Assert.Equal(new Vector(-1, 0, 0), r.XAxis);
        Assert.Equal(new Vector(0, 1, 0), r.YAxis);
        Assert.Equal(new Vector(0, 0, -1), r.ZAxis);
        Oracle.SameRotation(Rotation.FromAxisAngle(Vector.YAxis, 180), r, 1e-12);
        Oracle.SameRotation(Rotation.FromAxisAngle(Vector.XAxis, 180), Rotation.FlippedAroundX, 1e-12);
        Oracle.SameRotation(Rotation.FromAxisAngle(Vector.ZAxis, 180), Rotation.FlippedAroundZ, 1e-12);
        Assert.Equal("[[-1, 0, 0], [0, 1, 0], [0, 0, -1]]", r.ToOrientationString());
    }

    [Fact]
    public void ToQuaternionString_GermanCulture_FourDecimalsInvariant()
    {
        Rotation r = Rotation.FromAxisAngle(new Vector(1, 2, 3), 40);
        Assert.Equal("[0.9397, 0.0914, 0.1828, 0.2742]", Oracle.UnderGerman(r.ToQuaternionString));
    }

    [Fact]
    public void FromAxes_NonOrthogonalInput_KeepsXDirectionAndXYPlane()
    {
        Rotation r = Rotation.FromAxes(new Vector(2, 0, 0), new Vector(5, 3, 0));
        Oracle.SameRotation(Rotation.Identity, r, 1e-12);
        Rotation t = Rotation.FromAxes(new Vector(1, 1, 0), new Vector(0, 1, 1));
        Oracle.SameVector(new Vector(S, S, 0), t.XAxis, 1e-15);
        Vector y = new Vector(-0.5, 0.5, 1).Normalized();
        Oracle.SameVector(y, t.YAxis, 1e-15);
        Oracle.SameVector(Vector.Cross(t.XAxis, y), t.ZAxis, 1e-15);
    }

    [Theory]
    [InlineData(0, 0, 0, 0, 1, 0)]
    [InlineData(1, 0, 0, 0, 0, 0)]
    [InlineData(1, 0, 0, 3, 0, 0)]
    [InlineData(1, 2, 3, -2, -4, -6)]
    [InlineData(1, 0, 0, double.NaN, 1, 0)]
    public void FromAxes_ZeroParallelOrNaN_ThrowsArgumentException(double x0, double x1, double x2, double y0, double y1, double y2)
    {
        Assert.Throws<ArgumentException>(() => Rotation.FromAxes(x0, x1, x2, y0, y1, y2));
    }

    [Fact]
    public void ToAxisAngle_Identity_ZeroAxisZeroAngle()
    {
        AxisAngle aa = Rotation.Identity.ToAxisAngle();
        Assert.Equal(Vector.Zero, aa.Axis);
        Assert.Equal(0, aa.Angle);
        Assert.Equal("AxisAngle[0, 0, 0, 0]", aa.ToString());
    }

    [Theory]
    [InlineData(0, 0, 1, 90, 0, 0, 1, 90)]
    [InlineData(0, 0, 1, -90, 0, 0, -1, 90)]
    [InlineData(0, 1, 0, 270, 0, -1, 0, 90)]
    [InlineData(1, 0, 0, 400, 1, 0, 0, 40)]
    [InlineData(0, 3, 4, 179, 0, 0.6, 0.8, 179)]
    public void ToAxisAngle_AnyAngle_CanonicalRange0To180(double x, double y, double z, double deg, double ex, double ey, double ez, double eDeg)
    {
        AxisAngle aa = Rotation.FromAxisAngle(x, y, z, deg).ToAxisAngle();
        Oracle.SameVector(new Vector(ex, ey, ez), aa.Axis, 1e-12);
        Assert.Equal(eDeg, aa.Angle, 10);
    }

    public static TheoryData<double, double, double> HalfTurnAxes => new()
    {
        { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 }, { S, S, 0 }, { 0, S, -S }, { -S, 0, S }, { 1, 1, 1 }, { 1, -2, 3 }, { -0.1, 0.1, -5 },
    };

    [Theory]
    [MemberData(nameof(HalfTurnAxes))]
    public void HalfTurn_AnyAxis_RoundTripsThroughMatrixAndAxisAngle(double x, double y, double z)
    {
        Rotation r = Rotation.FromAxisAngle(x, y, z, 180);
        Rotation back = r.ToMatrix().ToRotation();
        Oracle.SameRotation(r, back, 1e-9);
        AxisAngle aa = back.ToAxisAngle();
        Assert.Equal(180, aa.Angle, 9);
        Vector n = new Vector(x, y, z).Normalized();
        Assert.Equal(1, Math.Abs(Vector.Dot(n, aa.Axis)), 12);
        Oracle.SameRotation(r, aa.ToRotation(), 1e-9);
        Oracle.SameRotation(r, aa.ToRotation().ToMatrix().ToRotation(), 1e-9);
    }

    [Fact]
    public void HalfTurnDiagonalXY_MatrixHandDerived_ShepperdYBranch()
    {
        RotationMatrix m = Rotation.FromAxisAngle(1, 1, 0, 180).ToMatrix();
        // 2nnᵀ − I with n = (1,1,0)/√2.
        Assert.Equal("RotationMatrix[[0, 1, 0], [1, 0, 0], [0, 0, -1]]", m.ToString());
        Rotation q = RotationMatrix.FromRows(0, 1, 0, 1, 0, 0, 0, 0, -1).ToRotation();
        Assert.Equal(0, q.W, 15);
        Assert.Equal(S, Math.Abs(q.X), 15);
        Assert.Equal(S, Math.Abs(q.Y), 15);
        Assert.Equal(0, q.Z, 15);
    }

    [Fact]
    public void TinyAngle_OneNanodegree_AxisAndAnglePreserved()
    {
        Rotation r = Rotation.FromAxisAngle(new Vector(0, 2, 0), 1e-9);
        AxisAngle aa = r.ToAxisAngle();
        Assert.Equal(1e-9, aa.Angle, 1e-20);
        Oracle.SameVector(Vector.YAxis, aa.Axis, 1e-12);
        Assert.Equal(1e-9, r.AngleTo(Rotation.Identity), 1e-20);
        Assert.False(r == Rotation.Identity);
        Assert.True(r.IsSimilar(Rotation.Identity));
        Assert.False(r.IsSimilar(Rotation.Identity, 1e-10));
        Oracle.SameRotation(r, r.ToMatrix().ToRotation(), 1e-12);
    }

    [Fact]
    public void IsSimilar_NegatedQuaternion_SameRotation()
    {
        Rotation r = Rotation.FromQuaternion(0.5, 0.5, 0.5, 0.5);
        Rotation neg = Rotation.FromQuaternion(-0.5, -0.5, -0.5, -0.5);
        Assert.NotEqual(r, neg);
        Assert.True(r.IsSimilar(neg));
        Assert.Equal(0, r.AngleTo(neg), 12);
        Assert.Equal(120, r.AngleTo(Rotation.Identity), 10);
        Assert.Equal(120, r.ToAxisAngle().Angle, 10);
        Assert.Equal(120, neg.ToAxisAngle().Angle, 10);
        Oracle.SameVector(r.ToAxisAngle().Axis, neg.ToAxisAngle().Axis, 1e-15);
    }

    [Fact]
    public void AngleTo_TwoRotations_MatchesRelativeRotationAngle()
    {
        Rotation a = Rotation.FromAxisAngle(Vector.ZAxis, 10), b = Rotation.FromAxisAngle(Vector.ZAxis, 55);
        Assert.Equal(45, a.AngleTo(b), 10);
        Assert.Equal(45, b.AngleTo(a), 10);
        Assert.True(a.IsSimilar(b, 45.0001));
        Assert.False(a.IsSimilar(b, 44.999));
    }

    [Fact]
    public void Multiply_LongChain_StaysUnitAndAccurate()
    {
        Rotation step = Rotation.FromAxisAngle(new Vector(1, 2, 2), 1);
        Rotation r = Rotation.Identity;
        for (int i = 0; i < 3600; i++)
        {
            r *= step;
        }
        Assert.Equal(1, r.W * r.W + r.X * r.X + r.Y * r.Y + r.Z * r.Z, 13);
        Oracle.SameRotation(Rotation.Identity, r, 1e-8);
    }
}
