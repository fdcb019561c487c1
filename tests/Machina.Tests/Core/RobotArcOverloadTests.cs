namespace Machina.Tests.Core;

/// <summary>The original's 18-number ArcMotionTo overload.</summary>
public class RobotArcOverloadTests
{
    [Fact]
    public void ArcMotionTo_EighteenNumbers_IssuesThePlaneArc()
    {
        var bot = Robot.Create("Bot", RobotType.ABB);
        bot.MoveTo(0, 0, 0);

        bot.ArcMotionTo(10, 10, 0, 1, 0, 0, 0, 1, 0, 20, 0, 0, -1, 0, 0, 0, -1, 0);

        var expected = new ActionArcMotion(new Plane(10, 10, 0, 1, 0, 0, 0, 1, 0), new Plane(20, 0, 0, -1, 0, 0, 0, -1, 0), false, false);
        Assert.Equal(expected, bot.GetProgramActions()[^1]);
        Assert.Equal("ArcMotionTo(10,10,0,1,0,0,0,1,0,20,0,0,-1,0,0,0,-1,0);", bot.GetProgramActions()[^1].ToInstruction());
        Assert.Equal(new Point(20, 0, 0), bot.GetCurrentPosition());
        Assert.Equal(Rotation.FlippedAroundZ, bot.GetCurrentRotation());
    }
}
