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
    public void SettingsBeyondAMillion_AreRefused_AndAMillionIsKept()
    {
        var bot = Robot.Create("Bot", RobotType.ABB);
        bot.SpeedTo(1e6);
        bot.AccelerationTo(1e6);
        bot.PrecisionTo(1e6);
        bot.ExtrusionRateTo(1e6);

        AssertRefusedAndUnchanged(bot, () => bot.Speed(1), "the speed would become 1000001 mm/s; settings are refused beyond 1,000,000 mm/s, which no robot or printer uses");
        AssertRefusedAndUnchanged(bot, () => bot.Acceleration(double.MaxValue), "the acceleration would become 1.79769313486232E+308 mm/s^2; settings are refused beyond 1,000,000 mm/s^2");
        AssertRefusedAndUnchanged(bot, () => bot.Precision(0.5), "the precision would become 1000000.5 mm; settings are refused beyond 1,000,000 mm");
        AssertRefusedAndUnchanged(bot, () => bot.ExtrusionRateTo(1e300), "the extrusion rate would become 1E+300 mm/mm; settings are refused beyond 1,000,000 mm/mm");
        AssertRefusedAndUnchanged(bot, () => bot.SpeedTo(double.MaxValue), "the speed would become 1.79769313486232E+308 mm/s; settings are refused");
        Assert.Equal(1e6, bot.GetCurrentSpeed());
        Assert.Equal(1e6, bot.GetCurrentAcceleration());
    }

    [Fact]
    public void AxesArmAngleExternalAxisAndTemperatureOverflow_AreRefused()
    {
        var bot = Robot.Create("Bot", RobotType.ABB);
        bot.AxesTo(0, 0, 1e6, 0, 0, 0);
        bot.ArmAngleTo(-1e6);
        bot.ExternalAxisTo(2, -double.MaxValue);
        bot.TemperatureTo(1e6, RobotPartType.Bed);

        AssertRefusedAndUnchanged(bot, () => bot.Axes(0, 0, double.MaxValue, 0, 0, 0), "the joint angles would become [0, 0, 1.79769313486232E+308, 0, 0, 0] degrees; joint values are refused beyond 1,000,000 degrees");
        AssertRefusedAndUnchanged(bot, () => bot.ArmAngle(-double.MaxValue), "the arm angle would become -1.79769313486232E+308 degrees; joint values are refused");
        AssertRefusedAndUnchanged(bot, () => bot.ArmAngle(-1), "the arm angle would become -1000001 degrees; joint values are refused beyond 1,000,000 degrees");
        AssertRefusedAndUnchanged(bot, () => bot.ExternalAxis(2, -double.MaxValue), "external axis 2 would become too large to represent");
        AssertRefusedAndUnchanged(bot, () => bot.Temperature(1, RobotPartType.Bed), "the Bed temperature would become 1000001 C; settings are refused beyond 1,000,000 C");
        AssertRefusedAndUnchanged(bot, () => bot.Temperature(double.MaxValue, RobotPartType.Bed), "the Bed temperature would become 1.79769313486232E+308 C; settings are refused");
    }

    [Fact]
    public void WaitsAnalogValuesAndToolsBeyondWhatALanguageHolds_AreRefused()
    {
        var bot = Robot.Create("Bot", RobotType.ABB);
        bot.Wait(1_000_000_000);
        bot.WriteAnalog("AO_1", -1e6);

        AssertRefusedAndUnchanged(bot, () => bot.Wait(1_000_000_001), "a wait of 1000000001 ms is refused: waits are limited to 1,000,000,000 ms (1,000,000 s, about 11.6 days)");
        AssertRefusedAndUnchanged(bot, () => bot.Wait(long.MaxValue), "a wait of 9223372036854775807 ms is refused");
        AssertRefusedAndUnchanged(bot, () => bot.WriteAnalog("AO_1", 1e300), "the analog output AO_1 would be set to 1E+300; analog values are refused beyond ±1,000,000");
        AssertRefusedAndUnchanged(bot, () => bot.DefineTool("Heavy", 0, 0, 100, 1, 0, 0, 0, 1, 0, 1e300, 0, 0, 50), "tool \"Heavy\" would weigh 1E+300 kg; tool weights are refused beyond 1,000,000 kg");
        AssertRefusedAndUnchanged(bot, () => bot.DefineTool("Long", new Vector(0, 0, 2e6), Rotation.Identity), "tool \"Long\" has its tip at [0, 0, 2000000] mm");
        Assert.Equal(-1e6, bot.GetCurrentState().AnalogOutputs["AO_1"]);
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
    public void ExtrusionRateThatWouldOverflowTheExtrudedLength_IsRefusedAsASetting()
    {
        // The rate is bounded (1,000,000 mm/mm), and so is a move (1 km): the extruded length cannot overflow any more.
        var bot = Robot.Create("Bot", RobotType.ZMORPH);
        bot.MoveTo(0, 0, 0);
        bot.Extrude();

        AssertRefusedAndUnchanged(bot, () => bot.ExtrusionRateTo(1e305), "the extrusion rate would become 1E+305 mm/mm; settings are refused");
        bot.ExtrusionRateTo(1e6);
        bot.MoveTo(1e6, 0, 0);
        Assert.Equal(new Point(1e6, 0, 0), bot.GetCurrentPosition());
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
