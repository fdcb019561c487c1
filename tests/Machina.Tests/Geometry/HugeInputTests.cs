namespace Machina.Tests.Geometry;

/// <summary>Non-normalised input with finite but huge components must not overflow into a wrong rotation.</summary>
public class HugeInputTests
{
    [Fact]
    public void FromAxisAngle_HugeAxis_GivesTheSameRotationAsTheUnitAxis()
    {
        Rotation r = Rotation.FromAxisAngle(new Vector(1e200, 0, 0), 90);

        Oracle.SameRotation(Rotation.FromAxisAngle(Vector.XAxis, 90), r, 1e-12);
        Assert.Equal(Math.Sqrt(0.5), r.W, 15);
        Assert.Equal(Math.Sqrt(0.5), r.X, 15);
    }

    [Fact]
    public void FromQuaternion_HugeComponents_IsScaledToUnitLength()
    {
        Rotation r = Rotation.FromQuaternion(1e200, 1e200, 0, 0);

        Assert.Equal(Math.Sqrt(0.5), r.W, 15);
        Assert.Equal(Math.Sqrt(0.5), r.X, 15);
        Assert.Equal(0, r.Y);
        Assert.Equal(0, r.Z);
        Assert.Equal(1, Rotation.FromQuaternion(double.MaxValue, 0, 0, 0).W);
    }

    [Fact]
    public void Robot_RotateAboutHugeAxis_TurnsTheTool()
    {
        var bot = Robot.Create("Bot", RobotType.ABB);
        bot.MoveTo(0, 0, 0);

        bot.Rotate(0, 0, 1e300, 90);

        Oracle.SameRotation(Rotation.FromAxisAngle(Vector.ZAxis, 90) * Rotation.FlippedAroundY, bot.GetCurrentRotation()!.Value, 1e-12);
    }

    [Fact]
    public void AngleBetweenDegrees_HugeVectors_IsTheAngleNotNaN()
    {
        Assert.Equal(90, Vector.AngleBetweenDegrees(new Vector(1e200, 0, 0), new Vector(0, 1e300, 0)), 12);
        Assert.Equal(45, Vector.AngleBetweenDegrees(new Vector(double.MaxValue, 0, 0), new Vector(double.MaxValue, double.MaxValue, 0)), 12);
    }

    [Fact]
    public void AngleBetweenDegrees_TinyAngle_IsNotRoundedToZero()
    {
        double expected = Math.Atan(1e-10) * 180 / Math.PI;

        Assert.Equal(expected, Vector.AngleBetweenDegrees(Vector.XAxis, new Vector(1, 1e-10, 0)), expected * 1e-9);
        Assert.Equal(180 - expected, Vector.AngleBetweenDegrees(Vector.XAxis, new Vector(-1, 1e-10, 0)), 1e-12);
    }
}
