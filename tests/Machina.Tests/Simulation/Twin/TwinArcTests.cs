using Machina.Simulation.Twin;

namespace Machina.Tests.Simulation.Twin;

/// <summary>
/// The circle of a circular motion: through the start, the via point and the end in that order (also the long way round), points at
/// a fraction of its length, the three ways the tool turns, and the points that do not define a circle.
/// </summary>
public class TwinArcTests
{
    private static readonly Rotation Down = new(1, 0, 0, 180);

    [Fact]
    public void ThreeQuarterCircle_GoesThroughTheViaPoint_TheLongWayRound()
    {
        // Centre (500, 0, 300), radius 100: start at 0°, via at 270° (below), end at 90°.
        var start = new Pose(new Vector(600, 0, 300), Down);
        var end = new Pose(new Vector(500, 100, 300), Down);
        TwinArc arc = TwinArc.Through(start, new Vector(500, -100, 300), end, TwinArcOrientation.Even)!;

        Assert.Equal(0, Vector.Distance(arc.Centre, new Vector(500, 0, 300)), 9);
        Assert.Equal(100, arc.Radius, 9);
        Assert.Equal(270, arc.SweepDegrees, 9);
        Assert.Equal(100 * 1.5 * Math.PI, arc.LengthMm, 9);
        Assert.Equal(0, Vector.Distance(arc.At(1.0 / 3).Position, new Vector(500, -100, 300)), 9);  // the via point, a third of the way
        Assert.Equal(0, Vector.Distance(arc.At(2.0 / 3).Position, new Vector(400, 0, 300)), 9);
        Assert.Equal(0, Vector.Distance(arc.At(0.5).Position, new Vector(500 - 100 * Math.Cos(Math.PI / 4), -100 * Math.Sin(Math.PI / 4), 300)), 9);
        Assert.Equal(end, arc.At(1));
        Assert.Equal(start, arc.At(0));
    }

    [Fact]
    public void Orientation_Even_PathRelative_AndFixed_TurnTheToolAsTheirControllersDo()
    {
        // A quarter circle counter-clockwise about z; the end orientation is the start's turned 90° about z (the same orientation to the path).
        var start = new Pose(new Vector(600, 0, 300), Down);
        var end = new Pose(new Vector(500, 100, 300), new Rotation(0, 0, 1, 90) * Down);
        var via = new Vector(500 + 100 * Math.Cos(Math.PI / 4), 100 * Math.Sin(Math.PI / 4), 300);
        Rotation turned30 = new Rotation(0, 0, 1, 30) * Down;

        // Even and path-relative agree here (the turn is about the circle's axis): 30° at a third.
        Assert.Equal(0, TwinRotation.AngleDegrees(TwinArc.Through(start, via, end, TwinArcOrientation.Even)!.At(1.0 / 3).Rotation, turned30), 6);
        Assert.Equal(0, TwinRotation.AngleDegrees(TwinArc.Through(start, via, end, TwinArcOrientation.PathRelative)!.At(1.0 / 3).Rotation, turned30), 6);

        // With the same absolute orientation at both ends, even keeps it; path-relative keeps it too (it turns back against the path).
        var sameEnd = new Pose(end.Position, Down);
        Assert.Equal(0, TwinRotation.AngleDegrees(TwinArc.Through(start, via, sameEnd, TwinArcOrientation.Even)!.At(0.5).Rotation, Down), 6);
        Assert.Equal(0, TwinRotation.AngleDegrees(TwinArc.Through(start, via, sameEnd, TwinArcOrientation.PathRelative)!.At(0.5).Rotation, Down), 6);

        // Fixed to the path ignores the end's orientation and turns with the circle: 45° half way, 90° at the end.
        TwinArc fixedArc = TwinArc.Through(start, via, sameEnd, TwinArcOrientation.FixedToPath)!;
        Assert.Equal(0, TwinRotation.AngleDegrees(fixedArc.At(0.5).Rotation, new Rotation(0, 0, 1, 45) * Down), 6);
        Assert.Equal(0, TwinRotation.AngleDegrees(fixedArc.End.Rotation, new Rotation(0, 0, 1, 90) * Down), 6);
        Assert.Equal(0, Vector.Distance(fixedArc.End.Position, sameEnd.Position), 12);
    }

    [Theory]
    [InlineData(550, 0, 300)]        // on the line from the start to the end
    [InlineData(600.05, 0, 300)]     // 0.05 mm from the start
    [InlineData(400, 0.05, 300)]     // 0.05 mm from the end
    [InlineData(700, 0, 300)]        // on the line, beyond the start
    public void PointsThatDoNotDefineACircle_GiveNone(double x, double y, double z)
    {
        var start = new Pose(new Vector(600, 0, 300), Down);
        var end = new Pose(new Vector(400, 0, 300), Down);

        Assert.Null(TwinArc.Through(start, new Vector(x, y, z), end, TwinArcOrientation.Even));
        Assert.NotNull(TwinArc.Through(start, new Vector(500, 0.2, 300), end, TwinArcOrientation.Even)); // 0.2 mm off the line: a huge circle, but one
    }
}
