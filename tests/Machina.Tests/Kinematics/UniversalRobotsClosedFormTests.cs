namespace Machina.Tests.Kinematics;

/// <summary>
/// The UR solver's configuration and singularity measure come from a closed form of the wrist centre (no forward kinematics): they
/// must agree with the same quantities read off the forward kinematics, on every UR arm and all over the joint space.
/// </summary>
public class UniversalRobotsClosedFormTests
{
    public static TheoryData<string> UrModels()
    {
        var data = new TheoryData<string>();
        foreach (RobotModel m in RobotModels.All.Where(m => m.Kinematics is UniversalRobotsKinematics))
        {
            data.Add(m.Name);
        }
        return data;
    }

    [Theory]
    [MemberData(nameof(UrModels))]
    public void ConfigurationAndMeasure_AgreeWithTheForwardKinematics(string name)
    {
        RobotModel model = RobotModels.Get(name);
        var kin = (UniversalRobotsKinematics)model.Kinematics;
        UniversalRobotsDh dh = kin.Parameters;
        var random = new Random(4546);
        int lefts = 0, checkedCount = 0;
        for (int i = 0; i < 5000; i++)
        {
            var j = new Joints(Angle(random), Angle(random), Angle(random), Angle(random), Angle(random), Angle(random));
            // The wrist centre from the forward kinematics: the flange less d6 along its axis.
            Pose flange = kin.Forward(j);
            Vector axis = flange.Rotation.Rotate(new Vector(0, 0, 1));
            double px = flange.Position.X - dh.D6 * axis.X, py = flange.Position.Y - dh.D6 * axis.Y;
            double delta = j.J1 * Angles.ToRadians - Math.Atan2(py, px) - Math.PI / 2;
            double sine = Math.Sin(delta);
            SingularityMeasure measure = ((ISolver)kin).Measure(j);
            Assert.Equal(Math.Abs(Math.Sqrt(px * px + py * py) - Math.Abs(dh.D4)), measure.ShoulderMm, 1e-6);
            if (Math.Abs(sine) < 1e-9)
            {
                continue;   // the wrist centre on the line between the two shoulder branches: either answer is right
            }
            ArmConfiguration config = kin.ConfigurationOf(j);
            Assert.True((sine < 0) == config.ShoulderBack, $"{name} at {j}: the forward kinematics say shoulder back {sine < 0}");
            lefts += sine < 0 ? 1 : 0;
            checkedCount++;
        }
        // Both branches were met, so a sign mistake could not pass.
        Assert.InRange(lefts, 500, checkedCount - 500);
    }

    [Theory]
    [InlineData(0.0)]
    [InlineData(-1e-300)]
    [InlineData(1.0)]
    [InlineData(-1.0)]
    [InlineData(Math.PI / 2)]
    [InlineData(3.1415)]
    [InlineData(-3.1415)]
    [InlineData(Math.PI)]
    [InlineData(-Math.PI)]
    [InlineData(4.0)]
    [InlineData(-4.0)]
    [InlineData(9.5)]
    [InlineData(double.NaN)]
    public void WrapDegrees_IsIeeeRemainderBitForBit(double radians)
    {
        double d = Math.IEEERemainder(radians * Angles.ToDegrees, 360.0);
        double expected = d <= -180.0 ? d + 360.0 : d;
        Assert.Equal(BitConverter.DoubleToInt64Bits(expected), BitConverter.DoubleToInt64Bits(KinematicsCore.WrapDegrees(radians)));
    }

    [Fact]
    public void WrapDegrees_KeepsNegativeZero() =>
        Assert.Equal(BitConverter.DoubleToInt64Bits(Math.IEEERemainder(-0.0, 360.0)), BitConverter.DoubleToInt64Bits(KinematicsCore.WrapDegrees(-0.0)));

    private static double Angle(Random random) => random.NextDouble() * 720 - 360;
}
