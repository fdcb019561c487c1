namespace Machina.Tests.Geometry;

/// <summary>Tiny turns survive conversion to axis-angle and rotation vector (only the exact identity has no axis).</summary>
public class TinyAngleTests
{
    [Theory]
    [InlineData(1e-13)]
    [InlineData(1e-15)]
    [InlineData(1e-20)]
    public void ToAxisAngleAndRotationVector_KeepTinyAngles(double degrees)
    {
        Rotation r = Rotation.FromAxisAngle(0, 0, 1, degrees);

        AxisAngle aa = r.ToAxisAngle();
        RotationVector rv = r.ToRotationVector();

        Assert.Equal(degrees, aa.Angle, degrees * 1e-9);
        Assert.Equal(Vector.ZAxis, aa.Axis);
        Assert.Equal(degrees, rv.Z, degrees * 1e-9);
        Assert.Equal(degrees, Rotation.Identity.AngleTo(rv.ToRotation()), degrees * 1e-9);
        Assert.Equal(degrees, Rotation.Identity.AngleTo(aa.ToRotation()), degrees * 1e-9);
    }

    [Fact]
    public void Identity_HasZeroAxisAndAngle()
    {
        Assert.Equal(new AxisAngle(Vector.Zero, 0), Rotation.Identity.ToAxisAngle());
        Assert.Equal(new RotationVector(0, 0, 0), Rotation.Identity.ToRotationVector());
        Assert.Equal(Rotation.Identity, new RotationVector(0, 0, 0).ToRotation());
    }
}
