namespace Machina.Tests.Kinematics;

public class ConfigurationTests
{
    private static readonly RobotModel Irb120 = RobotModels.Get("IRB 120");
    private static readonly RobotModel Kr6 = RobotModels.Get("KR 6 R900 sixx");

    [Theory]
    [InlineData(0, 0, 0, 0, 30, 0, "[0,0,0,0]")]
    [InlineData(100, 0, 0, -45, -30, 200, "[1,-1,2,1]")] // quadrants: 100° → 1, −45° → −1, 200° → 2; axis 5 negative
    [InlineData(0, -100, 60, 0, 30, 0, "[0,0,0,4]")]     // lower arm tilted back: wrist centre behind axis 1 (x ≈ −80 mm)
    [InlineData(0, 0, -110, 0, 30, 0, "[0,0,0,6]")]      // forearm folded up and back: behind axis 1 and behind the lower arm
    [InlineData(-90, 0, 0, -180, 30, -90, "[-1,-2,-1,0]")]
    public void AbbConfiguration_KnownJoints_GivesConfdata(double j1, double j2, double j3, double j4, double j5, double j6, string expected)
    {
        Assert.Equal(expected, AbbConfiguration.From(Irb120, new Joints(j1, j2, j3, j4, j5, j6)).ToRapid());
    }

    [Theory]
    [InlineData(0, -90, 90, 0, 45, 0, "S 'B010' T 'B000010'")]
    [InlineData(0, -90, 90, 0, 0, 0, "S 'B010' T 'B000010'")] // home: A5 = 0 is not a hand flip
    [InlineData(-10, -90, 90, 0, -45, -20, "S 'B110' T 'B110011'")]
    [InlineData(0, -90, -20, 0, 45, 0, "S 'B001' T 'B000110'")]
    [InlineData(-1e-13, -90, 90, -1e-14, 45, -2e-12, "S 'B010' T 'B000010'")] // the inverse kinematics' noise around 0 is 0, not negative
    [InlineData(-1e-6, -90, 90, 0, -1e-6, 0, "S 'B110' T 'B010011'")] // a real millionth of a degree below 0 is negative // forearm folded back over the top: A3 below the stretched angle (elbow bit cleared) and wrist point behind A1 (x ≈ −151 mm)
    public void KukaConfiguration_KnownJoints_GivesStatusAndTurn(double a1, double a2, double a3, double a4, double a5, double a6, string expected)
    {
        KukaConfiguration c = KukaConfiguration.From(Kr6, new Joints(a1, a2, a3, a4, a5, a6));
        Assert.Equal(expected, c.ToString());
    }

    [Fact]
    public void KukaConfiguration_ToKrl_IsAggregateFragment()
    {
        Assert.Equal("S 'B010',T 'B000010'", new KukaConfiguration(2, 2).ToKrl());
    }

    [Fact]
    public void Solve_EachAbbConfiguration_HasMatchingCfx()
    {
        RobotModel wide = RobotModel.FromOpw("IRB 120 wide", "ABB", Irb120.Opw!.Value, new Joints(-360, -360, -360, -360, -360, -360), new Joints(360, 360, 360, 360, 360, 360));
        Pose pose = wide.Kinematics.Forward(new Joints(20, -20, 40, 30, 40, 50));
        for (int cfx = 0; cfx < 8; cfx++)
        {
            Joints? j = wide.Kinematics.Solve(pose, ArmConfiguration.FromIndex(cfx));
            Assert.NotNull(j);
            Assert.Equal(cfx, AbbConfiguration.From(wide, j.Value).Cfx);
        }
    }

    [Fact]
    public void ArmConfiguration_FromIndexOutOfRange_Throws()
    {
        Assert.Throws<ArgumentOutOfRangeException>(() => ArmConfiguration.FromIndex(8));
    }
}
