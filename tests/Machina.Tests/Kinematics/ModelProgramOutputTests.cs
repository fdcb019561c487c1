namespace Machina.Tests.Kinematics;

public class ModelProgramOutputTests
{
    private static readonly CompileOptions Plain = new() { HumanComments = false };

    private static void AbbProgram(Robot bot)
    {
        bot.AxesTo(100, 0, 0, -45, 30, 200);
        bot.Move(0, 0, -10);
        bot.ArcMotion(10, 10, 0, 20, 0, 0);
    }

    private static void KukaProgram(Robot bot)
    {
        bot.AxesTo(-10, -90, 90, 10, -45, -20);
        bot.Move(0, 0, 10);
        bot.MotionMode("joint");
        bot.Move(0, 10, 0);
    }

    private static List<string> Lines(Robot bot, RobotType language, bool inline = true) =>
        bot.Compile(language, new CompileOptions { HumanComments = false, InlineTargets = inline }).Files.SelectMany(f => f.Lines)
            .Where(l => l.Contains("Move", StringComparison.Ordinal) || l.Contains("LIN", StringComparison.Ordinal) || l.Contains("PTP", StringComparison.Ordinal)
                || l.Contains("CIRC", StringComparison.Ordinal) || l.Contains("robtarget", StringComparison.Ordinal) || l.Contains("E6POS", StringComparison.Ordinal))
            .ToList();

    [Fact]
    public void Rapid_WithAbbModel_RobtargetsCarryConfdata()
    {
        var bot = Robot.Create("Demo", "ABB", "IRB 120");
        AbbProgram(bot);
        Assert.Equal(
        [
            "    MoveAbsJ [[100, 0, 0, -45, 30, 200], [9E9,9E9,9E9,9E9,9E9,9E9]], vel20, z5, Tool0\\WObj:=WObj0;",
            "    MoveL [[-38.2, 363.239, 594.544], [-0.2343, 0.4899, 0.6609, 0.518], [1,-1,2,0], [9E9,9E9,9E9,9E9,9E9,9E9]], vel20, z5, Tool0\\WObj:=WObj0;",
            "    MoveC [[-28.2, 373.239, 594.544], [-0.2343, 0.4899, 0.6609, 0.518], [0,0,0,0], [9E9,9E9,9E9,9E9,9E9,9E9]], " +
                "[[-18.2, 363.239, 594.544], [-0.2343, 0.4899, 0.6609, 0.518], [1,-1,2,0], [9E9,9E9,9E9,9E9,9E9,9E9]], vel20, z5, Tool0\\WObj:=WObj0;",
        ], Lines(bot, RobotType.ABB));
        Assert.Equal(
        [
            "  CONST robtarget target1 := [[-38.2, 363.239, 594.544], [-0.2343, 0.4899, 0.6609, 0.518], [1,-1,2,0], [9E9,9E9,9E9,9E9,9E9,9E9]];",
            "  CONST robtarget target2 := [[-28.2, 373.239, 594.544], [-0.2343, 0.4899, 0.6609, 0.518], [0,0,0,0], [9E9,9E9,9E9,9E9,9E9,9E9]];",
            "  CONST robtarget target3 := [[-18.2, 363.239, 594.544], [-0.2343, 0.4899, 0.6609, 0.518], [1,-1,2,0], [9E9,9E9,9E9,9E9,9E9,9E9]];",
        ], Lines(bot, RobotType.ABB, inline: false).Where(l => l.Contains("robtarget", StringComparison.Ordinal)));
        Assert.Equal("[1,-1,2,0]", AbbConfiguration.From(bot.Model!, bot.GetCurrentAxes()!.Value).ToRapid());
    }

    [Fact]
    public void Rapid_WithoutModel_ConfdataStaysZero()
    {
        var bot = Robot.Create("Demo", "ABB");
        bot.TransformTo(new Vector(-38.2, 373.239, 604.544), Rotation.FromQuaternion(-0.2343, 0.4899, 0.6609, 0.518));
        bot.Move(0, 0, -10);
        Assert.Equal(
            "    MoveL [[-38.2, 373.239, 594.544], [-0.2343, 0.4899, 0.6609, 0.518], [0,0,0,0], [9E9,9E9,9E9,9E9,9E9,9E9]], vel20, z5, Tool0\\WObj:=WObj0;",
            Lines(bot, RobotType.ABB)[1]);
    }

    [Fact]
    public void Rapid_WithUrModel_ConfdataStaysZero()
    {
        var bot = Robot.Create("Demo", RobotType.HUMAN);
        bot.SetModel("UR5e");
        bot.AxesTo(0, -90, 90, -90, -90, 0);
        bot.Move(0, 0, -10);
        Assert.Contains("[0,0,0,0]", Lines(bot, RobotType.ABB)[1]);
    }

    [Fact]
    public void Krl_WithKukaModel_E6PosCarriesStatusAndTurn()
    {
        var bot = Robot.Create("Demo", "KUKA", "KR 6 R900 sixx");
        KukaProgram(bot);
        Assert.Equal(
        [
            "  PTP $AXIS_ACT",
            "  PTP {AXIS: A1 -10, A2 -90, A3 90, A4 10, A5 -45, A6 -20} C_PTP",
            "  LIN {E6POS: X 492.243, Y 96.77, Z 955.709, A 28.431, B 45.542, C 6.147, S 'B110', T 'B110011'} C_DIS",
            "  PTP {E6POS: X 492.243, Y 106.77, Z 955.709, A 28.431, B 45.542, C 6.147, S 'B110', T 'B110011'} C_PTP",
        ], Lines(bot, RobotType.KUKA).Where(l => !l.Contains("WARNING", StringComparison.Ordinal)));
        Assert.Equal(
        [
            "DECL E6POS target2={X 492.243, Y 96.77, Z 955.709, A 28.431, B 45.542, C 6.147, S 'B110', T 'B110011'}",
            "DECL E6POS target3={X 492.243, Y 106.77, Z 955.709, A 28.431, B 45.542, C 6.147, S 'B110', T 'B110011'}",
        ], Lines(bot, RobotType.KUKA, inline: false).Where(l => l.StartsWith("DECL", StringComparison.Ordinal)));
    }

    [Fact]
    public void Krl_WithoutModel_NoStatusAndTurn()
    {
        var bot = Robot.Create("Demo", "KUKA");
        bot.TransformTo(new Vector(492.243, 96.77, 945.709), Rotation.Identity);
        bot.Move(0, 0, 10);
        Assert.Equal("  LIN {E6POS: X 492.243, Y 96.77, Z 955.709, A 0, B 0, C 0} C_DIS", Lines(bot, RobotType.KUKA)[2]);
    }
}
