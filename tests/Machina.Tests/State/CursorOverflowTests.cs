using Machina.Tests.Support;

namespace Machina.Tests.State;

/// <summary>Relative actions whose result would overflow to infinity are refused, with nothing changed and no id used.</summary>
public class CursorOverflowTests
{
    private static void AssertRefusedAndUnchanged(Robot bot, Action act, string reasonPart)
    {
        RobotState before = bot.GetCurrentState();
        int count = bot.GetProgramActions().Count;

        var ex = Assert.Throws<ActionRefusedException>(act);

        Assert.Contains(reasonPart, ex.Reason, StringComparison.Ordinal);
        StateAssert.Same(before, bot.GetCurrentState());
        Assert.Equal(count, bot.GetProgramActions().Count);
        bot.Wait(0);
        Assert.Equal(count + 1, bot.GetProgramActions()[^1].Id);
    }

    [Fact]
    public void Move_OverflowingThePosition_IsRefused()
    {
        var bot = Robot.Create("Bot", RobotType.ABB);
        bot.MoveTo(1e308, 0, 0);

        AssertRefusedAndUnchanged(bot, () => bot.Move(1e308, 0, 0), "the tool position would become [Infinity, 0, 0] mm, too far to represent");
        Assert.Equal(new Point(1e308, 0, 0), bot.GetCurrentPosition());
    }

    [Fact]
    public void Transform_OverflowingThePosition_IsRefused()
    {
        var bot = Robot.Create("Bot", RobotType.ABB);
        bot.MoveTo(0, 0, -1e308);

        AssertRefusedAndUnchanged(bot, () => bot.Transform(new Vector(0, 0, -1e308), Rotation.Identity), "too far to represent");
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
        bot.AxesTo(0, 0, double.MaxValue, 0, 0, 0);
        bot.ArmAngleTo(-double.MaxValue);
        bot.ExternalAxisTo(2, -double.MaxValue);
        bot.TemperatureTo(double.MaxValue, RobotPartType.Bed);

        AssertRefusedAndUnchanged(bot, () => bot.Axes(0, 0, double.MaxValue, 0, 0, 0), "the joint angles would become [0, 0, Infinity, 0, 0, 0] degrees");
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
        bot.ExtrusionRateTo(1e300);
        bot.Extrude();

        AssertRefusedAndUnchanged(bot, () => bot.MoveTo(1e10, 0, 0), "the extruded length would become too large to represent");
        Assert.Equal(new Point(0, 0, 0), bot.GetCurrentPosition());
    }
}
