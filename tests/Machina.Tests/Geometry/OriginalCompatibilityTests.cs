using System.Reflection;

namespace Machina.Tests.Geometry;

/// <summary>Members added so that code written for the original Machina.NET compiles and means what it meant there.</summary>
public class OriginalCompatibilityTests
{
    [Fact]
    public void RotationMatrix_New_IsTheIdentity_DefaultIsRefused()
    {
        var m = new RotationMatrix();

        Assert.Equal(RotationMatrix.Identity, m);
        Assert.True(m.IsRotation);
        Assert.True(m.IsIdentity());
        Assert.Equal(1, m.Determinant(), 15);
        Assert.Equal(Rotation.Identity, m.ToRotation());
        Assert.Equal(1, m.M00);
        Assert.Equal(0, m.M01);
        Assert.False(default(RotationMatrix).IsRotation);
        Assert.Throws<InvalidOperationException>(() => default(RotationMatrix).ToRotation());
    }

    [Fact]
    public void RotationMatrix_ObjectInitializer_StartsFromTheIdentity()
    {
        var m = new RotationMatrix { M00 = -1, M11 = -1 };

        Assert.Equal(1, m.M22);
        Assert.True(m.ToRotation().IsSimilar(Rotation.FlippedAroundZ));
    }

    [Fact]
    public void RotationMatrix_NineValues_AreOrthogonalisedAsTheOriginal()
    {
        var scaled = new RotationMatrix(2, 0, 0, 0, 3, 0, 0, 0, 1);
        var fromAxes = new RotationMatrix(new Vector(1, 1, 0), new Vector(1, -1, 0));

        Assert.True(scaled.IsIdentity());
        Assert.True(fromAxes.ZAxis.IsSimilar(new Vector(0, 0, -1), 1e-12));
        Assert.True(fromAxes.XAxis.IsSimilar(new Vector(Math.Sqrt(0.5), Math.Sqrt(0.5), 0), 1e-12));
        Assert.Throws<ArgumentException>(() => new RotationMatrix(1, 1, 0, 1, 1, 0, 0, 0, 0));
    }

    [Fact]
    public void RotationMatrix_Multiply_ComposesLikeRotations()
    {
        Rotation rz = Rotation.FromAxisAngle(Vector.ZAxis, 90), rx = Rotation.FromAxisAngle(Vector.XAxis, 90);

        RotationMatrix product = RotationMatrix.Multiply(rz.ToMatrix(), rx.ToMatrix());

        Assert.True(product.ToRotation().IsSimilar(rz * rx, 1e-9));
        Assert.Equal(120, product.ToAxisAngle().Angle, 9);
        Assert.Equal((rz * rx).ToRotationVector().X, product.ToRotationVector().X, 9);
    }

    [Fact]
    public void Rotation_AxisAngleConstructors_AreFromAxisAngle()
    {
        Assert.Equal(Rotation.FromAxisAngle(1, 2, 3, 40), new Rotation(1, 2, 3, 40));
        Assert.Equal(Rotation.FromAxisAngle(new Vector(0, 1, 0), -30), new Rotation(new Vector(0, 1, 0), -30));
        Assert.Throws<ArgumentException>(() => new Rotation(0, 0, 0, 90));
        Assert.Equal(Rotation.Identity, Rotation.GlobalXYZ);
        Assert.Equal(new Rotation(0, 0, 1, 30).Inverse(), Rotation.Inverse(new Rotation(0, 0, 1, 30)));
    }

    [Fact]
    public void Rotation_AxisAndAngle_AreCanonical()
    {
        var r = new Rotation(0, 0, 1, -90);

        Assert.True(r.Axis.IsSimilar(new Vector(0, 0, -1), 1e-12));
        Assert.Equal(90, r.Angle, 9);
        Assert.Equal(90, new Rotation(0, 0, 2, 90).Angle, 9);
        Assert.True(new Rotation(0, 0, 2, 90).Axis.IsSimilar(Vector.ZAxis, 1e-12));
        Assert.Equal(Vector.Zero, Rotation.Identity.Axis);
        Assert.Equal(0, Rotation.Identity.Angle);
    }

    [Fact]
    public void Rotation_ToOrientationAndToQuaternion_DescribeTheSameFrame()
    {
        var r = new Rotation(1, 1, 0, 120);

        Assert.Equal(r, r.ToOrientation().Rotation);
        Assert.Equal(r.W, r.ToQuaternion().W);
        Assert.Equal(r.Z, r.ToQuaternion().Z);
    }

    [Fact]
    public void Vector_DistanceAndProducts_AsTheOriginal()
    {
        var a = new Vector(1, 2, 3);
        var b = new Vector(4, 6, 3);

        Assert.Equal(5, a.DistanceTo(b), 15);
        Assert.Equal(25, Vector.SqDistance(a, b), 15);
        Assert.Equal(Vector.Dot(a, b), Vector.DotProduct(a, b));
        Assert.Equal(Vector.ZAxis, Vector.CrossProduct(Vector.XAxis, Vector.YAxis));
    }

    [Fact]
    public void Vector_AngleBetween_IsInRadiansAsTheOriginal()
    {
        Assert.Equal(Math.PI / 2, Vector.AngleBetween(Vector.XAxis, Vector.YAxis), 12);
        Assert.Equal(90, Vector.AngleBetweenDegrees(Vector.XAxis, Vector.YAxis), 12);
        Assert.Equal(0, Vector.AngleBetween(Vector.Zero, Vector.YAxis));
    }

    [Fact]
    public void Vector_DirectionTests_UseTheOriginalsTolerance()
    {
        Assert.True(Vector.AreParallel(new Vector(1, 0, 0), new Vector(5, 0, 0)));
        Assert.False(Vector.AreParallel(new Vector(1, 0, 0), new Vector(1, 1e-3, 0)));
        Assert.True(Vector.AreOrthogonal(Vector.XAxis, new Vector(0, 3, 3)));
        Assert.True(Vector.AreOpposite(Vector.XAxis, new Vector(-2, 0, 0)));
        Assert.False(Vector.AreOpposite(Vector.XAxis, Vector.XAxis));
    }

    [Fact]
    public void Vector_LengthHelpers_AsTheOriginal()
    {
        Assert.Equal(25, new Vector(3, 4, 0).SqLength(), 15);
        Assert.True(new Vector(0.6, 0.8, 0).IsUnit());
        Assert.False(new Vector(3, 4, 0).IsUnit());
    }

    [Fact]
    public void Joints_Norm_IsTheEuclideanLengthOfTheSixValues()
    {
        var j = new Joints(1, 2, 3, 4, 5, 6);

        Assert.Equal(91, j.NormSq(), 15);
        Assert.Equal(Math.Sqrt(91), j.Norm(), 15);
    }

    [Fact]
    public void RotationVector_OriginalGetters_ReadAxisAndAngle()
    {
        var rv = new RotationVector(0, 30, 40);

        Assert.Equal(50, rv.GetAngle(), 15);
        Assert.Equal(50, rv.Length(), 15);
        Assert.Equal(2500, rv.SqLength(), 15);
        Assert.Equal(new Vector(0, 0.6, 0.8), rv.GetVector());
        Assert.False(rv.IsZero());
        Assert.True(new RotationVector(0, 0, 1e-4).IsZero());
    }

    [Fact]
    public void ExternalAxes_OriginalNamesAndOneBasedAccessor()
    {
        var e = new ExternalAxes(100, null, 300);

        Assert.Equal(100, e.EA1);
        Assert.Null(e.EA2);
        Assert.Equal(300, e.EA3);
        Assert.Null(e.EA6);
        Assert.Equal(e.EA1, e.Axis(1));
        Assert.Equal(e.EA3, e.Axis(3));
        Assert.Equal(6, e.Length);
        Assert.Throws<ArgumentOutOfRangeException>(() => e.Axis(0));
    }

    [Fact]
    public void ExternalAxes_HasNoPublicIndexer_SoZeroBasedPortedCodeDoesNotCompile()
    {
        var publicIndexers = typeof(ExternalAxes).GetProperties(BindingFlags.Public | BindingFlags.Instance)
            .Where(p => p.GetIndexParameters().Length > 0);

        Assert.Empty(publicIndexers);
    }

    [Fact]
    public void Orientation_PresetsAndConversions_AsTheOriginal()
    {
        Assert.True(Orientation.WorldXZ.ZAxis.IsSimilar(new Vector(0, -1, 0), 1e-12));
        Assert.True(Orientation.WorldYZ.ZAxis.IsSimilar(new Vector(1, 0, 0), 1e-12));
        var o = new Orientation(0, 1, 0, -1, 0, 0);
        RotationMatrix m = o;
        Assert.Equal(o.ToRotationMatrix(), m);
        Assert.True(m.XAxis.IsSimilar(Vector.YAxis, 1e-12));
        Assert.Equal(90, o.ToRotationVector().Z, 9);
    }

    [Fact]
    public void AxisAngle_ToRotationVector_KeepsTheAngleAsGiven()
    {
        var aa = new AxisAngle(new Vector(0, 0, 2), 270);

        Assert.Equal(new RotationVector(0, 0, 270), aa.ToRotationVector());
        Assert.Equal(270 * Angles.ToRadians, aa.ToRotationVector(radians: true).Z, 12);
        Assert.True(aa.ToRotationMatrix().ToRotation().IsSimilar(new Rotation(0, 0, 1, -90), 1e-9));
        Assert.True(aa.ToYawPitchRoll().ToRotation().IsSimilar(new Rotation(0, 0, 1, -90), 1e-9));
        Assert.Equal(new RotationVector(0, 0, 0), new AxisAngle(Vector.Zero, 0).ToRotationVector());
    }

    [Fact]
    public void RotationVector_AxisAndAngleConstructor_ScalesTheUnitAxis()
    {
        var rv = new RotationVector(0, 0, 5, 90);

        Assert.Equal(new RotationVector(0, 0, 90), rv);
        Assert.Equal(new AxisAngle(Vector.ZAxis, 90), rv.ToAxisAngle());
        Assert.Equal(new AxisAngle(Vector.Zero, 0), new RotationVector(0, 0, 0).ToAxisAngle());
        Assert.Equal(new RotationVector(0, 0, 0), new RotationVector(0, 0, 0, 45));
        Assert.True(rv.ToRotationMatrix().ToRotation().IsSimilar(Rotation.FromAxisAngle(Vector.ZAxis, 90), 1e-9));
        Assert.Equal(90, rv.ToYawPitchRoll().Yaw, 9);
    }

    [Fact]
    public void YawPitchRoll_AviationNames_AreRollPitchYaw()
    {
        var ypr = new YawPitchRoll(10, 20, 30);

        Assert.Equal(10, ypr.Bank);
        Assert.Equal(20, ypr.Attitude);
        Assert.Equal(30, ypr.Heading);
        Assert.Equal(ypr.ToRotation().ToMatrix(), ypr.ToRotationMatrix());
    }

    [Fact]
    public void RobotEvents_OriginalHandlerDelegates_Subscribe()
    {
        var bot = Robot.Create("bot", RobotType.ABB);
        var issued = new List<ActionIssuedArgs>();
        bot.ActionIssued += new Robot.ActionIssuedHandler((_, e) => issued.Add(e));
        Robot.ActionIssuedHandler second = (sender, _) => Assert.Same(bot, sender);
        bot.ActionIssued += second;

        bot.MoveTo(300, 100, 500);

        ActionIssuedArgs args = Assert.Single(issued);
        Assert.IsType<ActionTranslation>(args.LastAction);
        Assert.Equal(new Vector(300, 100, 500), args.Position);
        Assert.Equal(args.ToJsonString(), args.ToJSONString());
    }

    [Fact]
    public void ActionReleasedArgs_PendingReleaseToDevice_IsPendingRelease()
    {
        var bot = Robot.Create("bot", RobotType.ABB);
        bot.MoveTo(300, 100, 500);

        var args = new ActionReleasedArgs(bot.GetProgramActions()[0], 3, bot.GetCurrentState());

        Assert.Equal(3, args.PendingReleaseToDevice);
        Assert.Equal(args.PendingRelease, args.PendingReleaseToDevice);
    }
}
