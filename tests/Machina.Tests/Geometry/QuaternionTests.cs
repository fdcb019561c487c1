namespace Machina.Tests.Geometry;

public class QuaternionTests
{
    private static void AssertQuaternion(double w, double x, double y, double z, Quaternion q, int digits = 4)
    {
        Assert.Equal(w, q.W, digits);
        Assert.Equal(x, q.X, digits);
        Assert.Equal(y, q.Y, digits);
        Assert.Equal(z, q.Z, digits);
    }

    /// <summary>q and −q are the same rotation: compare up to sign.</summary>
    private static void AssertSameRotation(double w, double x, double y, double z, Quaternion q)
    {
        double sign = w * q.W + x * q.X + y * q.Y + z * q.Z < 0 ? -1 : 1;
        AssertQuaternion(w, x, y, z, q * sign);
    }

    [Fact]
    public void NewAndDefault_AreBothTheIdentity()
    {
        AssertQuaternion(1, 0, 0, 0, new Quaternion(), 15);
        AssertQuaternion(1, 0, 0, 0, default, 15);
        Assert.Equal(Quaternion.Identity, default(Quaternion));
        Assert.True(new Quaternion().IsIdentity());
        Assert.Equal(Rotation.Identity, default(Quaternion).ToRotation());
    }

    [Fact]
    public void Constructor_KeepsComponentsAsGiven_ToRotationNormalises()
    {
        var q = new Quaternion(0.5, 2, 0, 0);

        AssertQuaternion(0.5, 2, 0, 0, q, 15);
        Assert.False(q.IsUnit());
        Rotation r = q.ToRotation();
        Assert.Equal(0.5 / Math.Sqrt(4.25), r.W, 12);
        Assert.Equal(2 / Math.Sqrt(4.25), r.X, 12);
    }

    [Fact]
    public void ToRotation_ZeroQuaternion_IsRefused()
    {
        var zero = new Quaternion(0, 0, 0, 0);

        Assert.True(zero.IsZero());
        Assert.Throws<ArgumentException>(() => zero.ToRotation());
        Assert.Throws<ArgumentException>(() => (Rotation)zero);
        Assert.Throws<ArgumentException>(() => new Quaternion(double.NaN, 0, 0, 0));
    }

    [Fact]
    public void YawPitchRollToQuaternion_SpecExample_IsQzQyQx()
    {
        // The original's documented example: (roll 10, pitch 20, yaw 30) → (0.9515, 0.0381, 0.1893, 0.2393).
        AssertQuaternion(0.9515, 0.0381, 0.1893, 0.2393, new YawPitchRoll(10, 20, 30).ToQuaternion());
    }

    [Theory]
    [InlineData(1, 1, 0, 1, -1, 0, 0, 0.9239, 0.3827, 0)]
    [InlineData(-1, 0, 0, 0, 0, -1, 0, 0, -0.7071, 0.7071)]
    [InlineData(-1, 0, 0, 0, 1, 0, 0, 0, 1, 0)]
    public void OrientationToQuaternion_SpecExamples(double x0, double x1, double x2, double y0, double y1, double y2,
        double w, double x, double y, double z)
    {
        var o = new Orientation(x0, x1, x2, y0, y1, y2);

        AssertSameRotation(w, x, y, z, o.ToQuaternion());
        Quaternion implicitly = o;
        Assert.Equal(o.ToQuaternion(), implicitly);
    }

    [Fact]
    public void Multiplication_LocalAndGlobal_MatchTheOriginalsExamples()
    {
        Quaternion rz = Rotation.FromAxisAngle(Vector.ZAxis, 90).ToQuaternion();
        Quaternion rx = Rotation.FromAxisAngle(Vector.XAxis, 90).ToQuaternion();

        AssertQuaternion(0.5, 0.5, 0.5, 0.5, rz * rx);
        AssertQuaternion(0.5, 0.5, -0.5, 0.5, rx * rz);
        Assert.Equal(rz * rx, Quaternion.Multiplication(rz, rx));
        AssertQuaternion(Rotation.Local(rz.ToRotation(), rx.ToRotation()).W, 0.5, 0.5, 0.5, rz * rx, 12);
    }

    [Fact]
    public void InverseAndDivision_UndoAProduct()
    {
        var q = new Quaternion(1, 2, 3, 4);
        var p = new Quaternion(0.5, -1, 0.25, 2);

        AssertQuaternion(1, 0, 0, 0, Quaternion.Inverse(q) * q, 12);
        AssertQuaternion(q.W, q.X, q.Y, q.Z, q * p / p, 12);
        Assert.Equal(Quaternion.Division(q, p), q / p);
        AssertQuaternion(1, -2, -3, -4, Quaternion.Conjugate(q), 15);
        Assert.Equal(new Quaternion(0, 0, 0, 0), Quaternion.Inverse(new Quaternion(0, 0, 0, 0)));
    }

    [Fact]
    public void AdditionSubtractionAndScale_AreComponentWise()
    {
        var q = new Quaternion(1, 2, 3, 4);
        var p = new Quaternion(4, 3, 2, 1);

        AssertQuaternion(5, 5, 5, 5, Quaternion.Addition(q, p), 15);
        AssertQuaternion(-3, -1, 1, 3, Quaternion.Subtraction(q, p), 15);
        // The original's static Scale returned an unscaled copy; this one scales.
        AssertQuaternion(2, 4, 6, 8, Quaternion.Scale(q, 2), 15);
        Assert.Equal(2 * q, q * 2);
        Assert.Equal(Math.Sqrt(30), q.Length(), 15);
        Assert.Equal(30, q.SqLength(), 15);
    }

    [Fact]
    public void IsEquivalent_NegatedQuaternion_IsTheSameRotation_DifferentOneIsNot()
    {
        var q = new Quaternion(0.5, 0.5, 0.5, 0.5);

        Assert.True(q.IsEquivalent(q * -1));
        Assert.True(q.IsEquivalent(q * 3));
        // The original compared component sums, so these two (both summing to 1) were "equivalent".
        Assert.False(new Quaternion(1, 0, 0, 0).IsEquivalent(new Quaternion(0, 1, 0, 0)));
        Assert.False(q.IsEquivalent(new Quaternion(0, 0, 0, 0)));
    }

    [Fact]
    public void Conversions_AgreeWithRotation()
    {
        Rotation r = Rotation.FromAxisAngle(new Vector(1, 2, 3), 47.5);
        Quaternion q = r;

        Assert.Equal(r.ToQuaternion(), q);
        Assert.True(r.IsSimilar((Rotation)q, 1e-9));
        Assert.True(r.IsSimilar(Rotation.FromQuaternion(q), 1e-9));
        Assert.Equal(47.5, q.ToAxisAngle().Angle, 9);
        Assert.True(q.ToAxisAngle().Axis.IsSimilar(new Vector(1, 2, 3).Normalized(), 1e-9));
        Assert.True(r.IsSimilar(q.ToRotationMatrix().ToRotation(), 1e-9));
        Assert.True(r.IsSimilar(q.ToYawPitchRoll().ToRotation(), 1e-9));
        Assert.Equal(47.5, q.ToRotationVector().Angle, 9);
        Assert.Equal(47.5 * Angles.ToRadians, q.ToRotationVector(radians: true).Angle, 9);
        Assert.True(r.ToMatrix().ToQuaternion().IsEquivalent(q));
        Assert.True(r.ToAxisAngle().ToQuaternion().IsEquivalent(q));
        Assert.True(r.ToRotationVector().ToQuaternion().IsEquivalent(q));
    }

    [Fact]
    public void ToString_FourDecimals_AsTheOriginal()
    {
        Assert.Equal("[0.7071, 0, 0, 0.7071]", Rotation.FromAxisAngle(Vector.ZAxis, 90).ToQuaternion().ToString());
    }
}
