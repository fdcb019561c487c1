using Machina.Tests.Support;

namespace Machina.Tests.State;

/// <summary>
/// Relative actions whose result would overflow to infinity, and targets beyond 1 km or 1,000,000 degrees, are refused, with
/// nothing changed and no id used; large but real targets (a gantry of tens of metres) are kept exactly.
/// </summary>
public class CursorOverflowTests
{
    private static void AssertRefusedAndUnchanged(Robot bot, Action act, string reasonPart)
    {
        RobotState before = bot.GetCurrentState();
        int count = bot.GetProgramActions().Count;

        var ex = Assert.Throws<ActionRefusedException>(act);

        Assert.True(ex.Reason.Contains(reasonPart, StringComparison.Ordinal), ex.Reason);
        StateAssert.Same(before, bot.GetCurrentState());
        Assert.Equal(count, bot.GetProgramActions().Count);
        bot.Wait(0);
        Assert.Equal(count + 1, bot.GetProgramActions()[^1].Id);
    }

    [Fact]
    public void Move_OverflowingThePosition_IsRefused()
    {
        var bot = Robot.Create("Bot", RobotType.ABB);
        bot.MoveTo(1e6, 0, 0);

        AssertRefusedAndUnchanged(bot, () => bot.Move(1e308, 0, 0), "the tool position would become [1E+308, 0, 0] mm; targets are refused beyond 1,000,000 mm");
        Assert.Equal(new Point(1e6, 0, 0), bot.GetCurrentPosition());
    }

    [Fact]
    public void Transform_OverflowingThePosition_IsRefused()
    {
        var bot = Robot.Create("Bot", RobotType.ABB);
        bot.MoveTo(0, 0, -1e6);

        AssertRefusedAndUnchanged(bot, () => bot.Transform(new Vector(0, 0, -1e308), Rotation.Identity), "the tool position would become [0, 0, -1E+308] mm; targets are refused");
    }

    [Fact]
    public void SettingsOverflow_IsRefused()
    {
        var bot = Robot.Create("Bot", RobotType.ABB);
        bot.SpeedTo(double.MaxValue);
        bot.AccelerationTo(double.MaxValue);
        bot.PrecisionTo(double.MaxValue);
        bot.ExtrusionRateTo(double.MaxValue);

        AssertRefusedAndUnchanged(bot, () => bot.Speed(double.MaxValue), "the speed would become too large to represent");
        AssertRefusedAndUnchanged(bot, () => bot.Acceleration(double.MaxValue), "the acceleration would become too large to represent");
        AssertRefusedAndUnchanged(bot, () => bot.Precision(double.MaxValue), "the precision would become too large to represent");
        AssertRefusedAndUnchanged(bot, () => bot.ExtrusionRate(double.MaxValue), "the extrusion rate would become too large to represent");
        Assert.Equal(double.MaxValue, bot.GetCurrentSpeed());
    }

    [Fact]
    public void AxesArmAngleExternalAxisAndTemperatureOverflow_AreRefused()
    {
        var bot = Robot.Create("Bot", RobotType.ABB);
        bot.AxesTo(0, 0, 1e6, 0, 0, 0);
        bot.ArmAngleTo(-double.MaxValue);
        bot.ExternalAxisTo(2, -double.MaxValue);
        bot.TemperatureTo(double.MaxValue, RobotPartType.Bed);

        AssertRefusedAndUnchanged(bot, () => bot.Axes(0, 0, double.MaxValue, 0, 0, 0), "the joint angles would become [0, 0, 1.79769313486232E+308, 0, 0, 0] degrees; joint values are refused beyond 1,000,000 degrees");
        AssertRefusedAndUnchanged(bot, () => bot.ArmAngle(-double.MaxValue), "the arm angle would become too large to represent");
        AssertRefusedAndUnchanged(bot, () => bot.ExternalAxis(2, -double.MaxValue), "external axis 2 would become too large to represent");
        AssertRefusedAndUnchanged(bot, () => bot.Temperature(double.MaxValue, RobotPartType.Bed), "the Bed temperature would become too large to represent");
    }

    [Fact]
    public void ExternalAxisReachingAbbsNoAxisMarker_IsRefusedInsteadOfSilentlyUnset()
    {
        var bot = Robot.Create("Bot", RobotType.ABB);
        bot.ExternalAxisTo(1, 5e9);

        AssertRefusedAndUnchanged(bot, () => bot.ExternalAxisTo(1, 9e9), "external axis 1 would become 9000000000; values from 9000000000 up mean \"no axis\"");
        AssertRefusedAndUnchanged(bot, () => bot.ExternalAxis(1, 4e9), "external axis 1 would become 9000000000; values from");
        Assert.Equal(5e9, bot.GetCurrentExternalAxes()!.Value[1]);
    }

    [Fact]
    public void ExtrudedLengthOverflow_RefusesTheMotion()
    {
        var bot = Robot.Create("Bot", RobotType.ZMORPH);
        bot.MoveTo(0, 0, 0);
        bot.ExtrusionRateTo(1e305);
        bot.Extrude();

        AssertRefusedAndUnchanged(bot, () => bot.MoveTo(1e6, 0, 0), "the extruded length would become too large to represent");
        Assert.Equal(new Point(0, 0, 0), bot.GetCurrentPosition());
    }

    [Fact]
    public void AbsurdTargets_AreRefusedAtIssueTime_WithTheBoundInTheReason()
    {
        var bot = Robot.Create("Bot", RobotType.ABB);
        bot.MoveTo(0, 0, 0);

        AssertRefusedAndUnchanged(bot, () => bot.MoveTo(1e308, 0, 0),
            "the tool position would become [1E+308, 0, 0] mm; targets are refused beyond 1,000,000 mm (1 km) from the origin along X, Y or Z, which no robot or printer reaches.");
        AssertRefusedAndUnchanged(bot, () => bot.MoveTo(0, -1000000.001, 0), "the tool position would become [0, -1000000.001, 0] mm;");
        AssertRefusedAndUnchanged(bot, () => bot.TransformTo(new Vector(0, 0, 2e6), Rotation.Identity), "the tool position would become [0, 0, 2000000] mm;");
        AssertRefusedAndUnchanged(bot, () => bot.ArcMotionTo(new Vector(1e7, 1e7, 0), new Vector(0, 10, 0)),
            "the arc's through point would be at [10000000, 10000000, 0] mm; targets are refused beyond 1,000,000 mm");
        AssertRefusedAndUnchanged(bot, () => bot.AxesTo(0, 0, 0, 0, 0, 1e308),
            "the joint angles would become [0, 0, 0, 0, 0, 1E+308] degrees; joint values are refused beyond 1,000,000 degrees (about 2,778 turns), which no robot reaches.");
        AssertRefusedAndUnchanged(bot, () => bot.Do("MoveTo(1e9,0,0);"), "the tool position would become [1000000000, 0, 0] mm;");
    }

    [Fact]
    public void LargeRealTargets_AtAndInsideTheBound_AreKeptExactly()
    {
        var bot = Robot.Create("Gantry", RobotType.ABB);
        bot.MoveTo(45000, -12000.5, 3000);
        bot.MoveTo(1e6, -1e6, 1e6);
        bot.AxesTo(1e6, -1e6, 0, 0, 0, 720);

        Assert.Equal(new Joints(1e6, -1e6, 0, 0, 0, 720), bot.GetCurrentAxes());
        bot.TransformTo(new Vector(45000, -12000.5, 3000), Rotation.FlippedAroundY);
        string program = bot.Compile().MainFile.ToText();
        Assert.True(program.Contains("MoveL [[45000, -12000.5, 3000], [0, 0, 1, 0]", StringComparison.Ordinal), program);
        Assert.Contains("MoveL [[1000000, -1000000, 1000000], [0, 0, 1, 0]", program, StringComparison.Ordinal);
        Assert.Contains("MoveAbsJ [[1000000, -1000000, 0, 0, 0, 720], [9E9", program, StringComparison.Ordinal);
    }
}
