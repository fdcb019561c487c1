namespace Machina.Tests.Geometry;

/// <summary>A matrix that is not a rotation (the all-zero default, a reflection, a scaled matrix) is never converted silently.</summary>
public class RotationMatrixValidityTests
{
    public static TheoryData<string, RotationMatrix> NotRotations => new()
    {
        { "default", default },
        { "reflection", new RotationMatrix { M00 = 1, M11 = 1, M22 = -1 } },
        { "scaled", new RotationMatrix { M00 = 2, M11 = 2, M22 = 2 } },
        { "sheared", new RotationMatrix { M00 = 1, M01 = 0.5, M11 = 1, M22 = 1 } },
    };

    [Theory]
    [MemberData(nameof(NotRotations))]
    public void ToRotationAndToYawPitchRoll_OfANonRotation_Throw(string name, RotationMatrix m)
    {
        Assert.False(m.IsRotation, name);
        var ex = Assert.Throws<InvalidOperationException>(() => m.ToRotation());
        Assert.Contains("is not a rotation matrix", ex.Message, StringComparison.Ordinal);
        Assert.Throws<InvalidOperationException>(() => m.ToYawPitchRoll());
    }

    [Fact]
    public void MatricesMadeByMachina_AreRotations()
    {
        RotationMatrix m = Rotation.FromAxisAngle(1, 2, 3, 123).ToMatrix();

        Assert.True(m.IsRotation);
        Oracle.SameRotation(Rotation.FromAxisAngle(1, 2, 3, 123), m.ToRotation(), 1e-12);
        Assert.True(RotationMatrix.FromRows(2, 0, 0, 0, 3, 0, 0, 0, 4).IsRotation);
        Assert.Equal(Rotation.Identity, new RotationMatrix { M00 = 1, M11 = 1, M22 = 1 }.ToRotation());
    }
}
