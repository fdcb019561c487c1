namespace Machina.Tests.State;

/// <summary>Arcs too large for double arithmetic are refused with the right reason, not called collinear.</summary>
public class ArcLimitTests
{
    [Fact]
    public void HugeArc_IsRefusedAsTooLarge()
    {
        var bot = Robot.Create("Bot", RobotType.ABB);
        bot.MoveTo(0, 0, 0);

        var ex = Assert.Throws<ActionRefusedException>(() => bot.ArcMotionTo(1e160, 1e160, 0, 2e160, 0, 0));

        Assert.Equal("the arc is too large to compute (its points are more than about 1E+77 mm apart).", ex.Reason);
        Assert.Equal(new Point(0, 0, 0), bot.GetCurrentPosition());
    }

    [Fact]
    public void LargeButComputableArc_IsRefusedBeyondTheCoordinateBound_AndAKilometreArcIsAccepted()
    {
        var bot = Robot.Create("Bot", RobotType.ABB);
        bot.MoveTo(0, 0, 0);

        var ex = Assert.Throws<ActionRefusedException>(() => bot.ArcMotionTo(1e60, 1e60, 0, 2e60, 0, 0));
        bot.ArcMotionTo(5e5, 5e5, 0, 1e6, 0, 0);

        Assert.Equal("the arc's through point would be at [1E+60, 1E+60, 0] mm; targets are refused beyond 1,000,000 mm (1 km) from the origin along X, Y or Z, which no robot or printer reaches.", ex.Reason);
        Assert.Equal(new Point(1e6, 0, 0), bot.GetCurrentPosition());
    }
}
