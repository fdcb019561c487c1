namespace Machina.Tests.Brands.UR;

/// <summary>Numbers a UR controller refuses or cannot follow, which the script would otherwise carry without a word.</summary>
public class UrScriptWarningTests
{
    private static bool IsBlend(ProgramWarning w) => w.Message.Contains("blend radius", StringComparison.Ordinal);

    [Fact]
    public void Compile_SpiralOfShortSegmentsWithPrecision1_WarnsEveryBlendLargerThanHalfASegment()
    {
        // 500 points 0.4 mm apart on a spiral: a 1 mm blend overlaps its neighbours everywhere.
        Robot bot = Robot.Create("Spiral", "UR");
        bot.MoveTo(300, 0, 300);
        bot.PrecisionTo(1);
        double angle = 0, radius = 20;
        for (int i = 0; i < 500; i++)
        {
            angle += 0.4 / radius;
            radius += 0.01;
            bot.MoveTo(300 + radius * Math.Cos(angle) - 20, radius * Math.Sin(angle), 300);
        }

        RobotProgram program = bot.Compile();
        ProgramWarning[] blends = [.. program.Warnings.Where(IsBlend)];

        // The start keeps Machina's default 5 mm blend, more than half of the first 0.4 mm step; then every spiral point.
        Assert.Equal(501, blends.Length);
        Assert.Equal(1, blends[0].ActionId);
        Assert.StartsWith("the blend radius of 5 mm is more than half of the next motion (0.4 mm long)", blends[0].Message, StringComparison.Ordinal);
        Assert.Equal(3, blends[1].ActionId);
        Assert.Equal("the blend radius of 1 mm is more than half of this motion (0.4 mm long); blends cannot overlap: a UR controller logs a warning and runs on (the twin blends with half of the motion). Use PrecisionTo(0.2) or less around short motions.", blends[1].Message);
    }

    [Fact]
    public void Compile_BlendLargerThanHalfTheNextSegment_WarnsTheMotionThatHasIt()
    {
        Robot bot = Robot.Create("Blend", "UR");
        bot.MoveTo(300, 0, 300);
        bot.PrecisionTo(5);
        bot.MoveTo(400, 0, 300);
        bot.PrecisionTo(0);
        bot.MoveTo(406, 0, 300);

        ProgramWarning w = Assert.Single(bot.Compile().Warnings, IsBlend);

        Assert.Equal(3, w.ActionId);
        Assert.StartsWith("the blend radius of 5 mm is more than half of the next motion (6 mm long)", w.Message, StringComparison.Ordinal);
    }

    [Fact]
    public void Compile_BlendsWithinHalfTheirSegments_NoWarning()
    {
        Robot bot = Robot.Create("Blend", "UR");
        bot.MoveTo(300, 0, 300);
        bot.PrecisionTo(5);
        bot.MoveTo(310, 0, 300);
        bot.MoveTo(320, 0, 300);

        Assert.DoesNotContain(bot.Compile().Warnings, IsBlend);
    }

    [Fact]
    public void Compile_JointSpeedAboveTheModelsMaximum_Warns()
    {
        Robot bot = Robot.Create("Fast", "UR", "UR5e");
        bot.AxesTo(0, -90, 90, -90, -90, 0);
        bot.SpeedTo(300);
        bot.AxesTo(90, -90, 90, -90, -90, 0);
        bot.MotionMode("joint");
        bot.SpeedTo(150);
        bot.MoveTo(300, 200, 400);

        RobotProgram program = bot.Compile();
        ProgramWarning w = Assert.Single(program.Warnings, x => x.Message.Contains("°/s", StringComparison.Ordinal));

        Assert.Equal(3, w.ActionId);
        Assert.Equal("joint motions take the speed as the speed of the joint that moves most, in degrees per second: 300°/s is above the UR5e's maximum of 180°/s for joint 1. Use SpeedTo(180) or less for joint motions.", w.Message);
        Assert.Contains(program.Files[0].Lines, l => l.StartsWith("  movej([1.570796,", StringComparison.Ordinal) && l.Contains("v=5.235988", StringComparison.Ordinal));
    }

    [Fact]
    public void Compile_JointSpeedWithoutAModel_NoWarning()
    {
        Robot bot = Robot.Create("Fast", "UR");
        bot.SpeedTo(300);
        bot.AxesTo(90, -90, 90, -90, -90, 0);

        Assert.Empty(bot.Compile().Warnings);
    }
}
