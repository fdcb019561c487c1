namespace Machina.Tests.State;

/// <summary>Extruded length = rate × path length of each motion while extruding (arcs use the arc length).</summary>
public class CursorExtrusionTests
{
    private static Robot Printer()
    {
        var bot = Robot.Create("Printer", RobotType.MARLIN);
        bot.MoveTo(0, 0, 0);
        bot.ExtrusionRateTo(0.5);
        bot.Extrude();
        return bot;
    }

    [Fact]
    public void Move_WhileExtruding_AddsRateTimesDistance()
    {
        var bot = Printer();
        bot.Move(30, 40, 0); // 50 mm
        Assert.Equal(25, bot.GetCurrentState().ExtrudedLength, 12);
        bot.MoveTo(30, 40, 100); // 100 mm
        Assert.Equal(75, bot.GetCurrentState().ExtrudedLength, 12);
    }

    [Fact]
    public void Move_NotExtruding_AddsNothing()
    {
        var bot = Printer();
        bot.Extrude(false);
        bot.Move(30, 40, 0);

        Assert.Equal(0, bot.GetCurrentState().ExtrudedLength);
    }

    [Fact]
    public void Rotate_WhileExtruding_AddsNothing()
    {
        var bot = Printer();
        bot.Rotate(0, 0, 1, 90);

        Assert.Equal(0, bot.GetCurrentState().ExtrudedLength);
    }

    [Fact]
    public void ArcMotionTo_QuarterCircle_AddsRateTimesArcLength()
    {
        var bot = Printer();
        bot.Extrude(false);
        bot.MoveTo(100, 0, 0);
        bot.Extrude(true);
        double h = 100 / Math.Sqrt(2);
        bot.ArcMotionTo(h, h, 0, 0, 100, 0); // quarter circle of radius 100: 50π mm

        Assert.Equal(0.5 * 50 * Math.PI, bot.GetCurrentState().ExtrudedLength, 9);
    }

    [Fact]
    public void ArcMotionTo_ThreeQuarterCircle_GoesThroughTheThroughPoint()
    {
        var bot = Printer();
        bot.Extrude(false);
        bot.MoveTo(100, 0, 0);
        bot.Extrude(true);
        bot.ArcMotionTo(-100, 0, 0, 0, -100, 0); // via the far side: 3/4 of 200π

        Assert.Equal(0.5 * 150 * Math.PI, bot.GetCurrentState().ExtrudedLength, 9);
    }

    [Fact]
    public void ArcMotion_RelativeHalfCircle_AddsRateTimesArcLength()
    {
        var bot = Printer();
        bot.ArcMotion(10, 10, 0, 20, 0, 0); // half circle of radius 10 centred at (10, 0, 0): 10π mm

        Assert.Equal(0.5 * 10 * Math.PI, bot.GetCurrentState().ExtrudedLength, 9);
        Assert.Equal(new Point(20, 0, 0), bot.GetCurrentPosition());
    }

    [Fact]
    public void AxesTo_WhileExtruding_WarnsAndKeepsTheLength()
    {
        var bot = Printer();
        bot.Move(10, 0, 0);
        var log = new List<LogEntry>();
        bot.Logger.Logged += (_, e) => log.Add(e);
        bot.AxesTo(0, 0, 0, 0, 90, 0);

        Assert.Equal(5, bot.GetCurrentState().ExtrudedLength, 12);
        LogEntry warning = Assert.Single(log, e => e.Level == LogLevel.WARNING);
        Assert.StartsWith("AxesTo(0,0,0,0,90,0); ", warning.Message);
    }

    [Fact]
    public void ExtrusionRate_RelativeAndPushPop_Restore()
    {
        var bot = Printer();
        bot.PushSettings();
        bot.ExtrusionRate(0.25);
        bot.Move(10, 0, 0);
        bot.PopSettings();
        bot.Move(10, 0, 0);

        Assert.Equal(0.75 * 10 + 0.5 * 10, bot.GetCurrentState().ExtrudedLength, 12);
    }
}
