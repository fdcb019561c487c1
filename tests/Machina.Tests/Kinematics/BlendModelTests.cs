namespace Machina.Tests.Kinematics;

/// <summary>The speed profile and blend geometry that the cycle-time estimate and the twins share, against numbers worked by hand.</summary>
public class BlendModelTests
{
    [Theory]
    [InlineData(0.1, 0.25, 1.2)] // reaches full speed
    [InlineData(0.01, 0.25, 1.2)] // a triangle
    [InlineData(2.0, 1.05, 1.4)]
    public void Plan_FromRestToRest_IsTheTrapezoid(double distance, double speed, double acceleration)
    {
        SpeedProfile profile = SpeedProfile.Plan(distance, 0, speed, 0, acceleration);

        Assert.Equal(MotionTiming.Trapezoid(distance, speed, acceleration), profile.Seconds, 12);
        Assert.Equal(distance / 2, profile.DistanceAt(profile.Seconds / 2), 12); // symmetric
        Assert.Equal(distance, profile.DistanceAt(profile.Seconds), 12);
    }

    [Fact]
    public void Plan_IntoABlend_EndsAtTheEntrySpeed()
    {
        // 80 mm from rest at 1.2 m/s² up to 0.25 m/s, entering a 20 mm zone at sqrt(2 * 1.2 * 0.02) = 0.219089 m/s:
        // 0.25/1.2 up + (0.25 - 0.219089)/1.2 down + (0.08 - 0.026042 - 0.006042)/0.25 cruise = 0.425759 s.
        double entry = BlendModel.EntrySpeed(0.08, 0, 0.25, 1.2, 0.02);
        SpeedProfile profile = SpeedProfile.Plan(0.08, 0, 0.25, entry, 1.2);

        Assert.Equal(0.219089, entry, 6);
        Assert.Equal(0.425759, profile.Seconds, 6);
        Assert.Equal(entry, profile.SpeedAt(profile.Seconds), 9);
        Assert.Equal(0.25, profile.SpeedAt(0.3), 9);
        Assert.Equal(0.5 * 1.2 * 0.1 * 0.1, profile.DistanceAt(0.1), 12);
        // What it takes to stop within the zone from there: v/a = 0.182574 s.
        Assert.Equal(0.182574, BlendModel.StopSeconds(0.02, entry, 1.2), 6);
    }

    [Fact]
    public void Plan_TooShortToChangeSpeed_ChangesItEvenly()
    {
        SpeedProfile profile = SpeedProfile.Plan(0.001, 0.2, 0.25, 0, 1.2); // 0.2 m/s cannot stop within 1 mm at 1.2 m/s²

        Assert.Equal(0.001 / 0.1, profile.Seconds, 12);
        Assert.Equal(0.1, profile.SpeedAt(profile.Seconds / 2), 9);
    }

    [Fact]
    public void Radius_IsAtMostHalfOfTheMotion_AndNoneForATurn()
    {
        Assert.Equal(0.02, BlendModel.Radius(0.02, 0.1));
        Assert.Equal(0.05, BlendModel.Radius(0.5, 0.1));
        Assert.Equal(0, BlendModel.Radius(0.005, 0));
        Assert.Equal(0, BlendModel.Radius(0, 0.1));
    }

    [Fact]
    public void Length_OfARightAngleBlend_IsTheParabolasLength()
    {
        // B(s) = (-(1-s)², s²): the length is ∫ 2 sqrt((1-s)² + s²) ds = 1.623225 (in units of the radius).
        double length = BlendModel.Length(new Vector(-1, 0, 0), Vector.Zero, new Vector(0, 1, 0));

        Assert.Equal(1.623225, length, 3);
        Assert.Equal(new Vector(-0.25, 0.25, 0), BlendModel.Point(new Vector(-1, 0, 0), Vector.Zero, new Vector(0, 1, 0), 0.5));
        Assert.Equal(2, BlendModel.Length(new Vector(-1, 0, 0), Vector.Zero, new Vector(1, 0, 0)), 9); // straight on: no shortcut
    }

    [Fact]
    public void PointAtDistance_WalksThePathEvenly()
    {
        Vector entry = new(-1, 0, 0), exit = new(0, 1, 0);
        double length = BlendModel.Length(entry, Vector.Zero, exit);

        Assert.Equal(entry, BlendModel.PointAtDistance(entry, Vector.Zero, exit, 0));
        Assert.Equal(0, (exit - BlendModel.PointAtDistance(entry, Vector.Zero, exit, length)).Length, 9);
        Vector middle = BlendModel.PointAtDistance(entry, Vector.Zero, exit, length / 2); // the parabola is symmetric: its middle is B(0.5)
        Assert.Equal(0, (middle - new Vector(-0.25, 0.25, 0)).Length, 9);
        // A tenth of the way is about a tenth of the length from the entry (not a tenth of the parameter, which runs faster there).
        Vector tenth = BlendModel.PointAtDistance(entry, Vector.Zero, exit, length / 10);
        Assert.Equal(length / 10, (tenth - entry).Length, 2);
    }
}
