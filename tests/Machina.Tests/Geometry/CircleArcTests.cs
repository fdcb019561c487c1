namespace Machina.Tests.Geometry;

public class CircleArcTests
{
    [Fact]
    public void TryCreate_HalfCircleClockwiseFromAbove_CentreRadiusSweepAndNormal()
    {
        Assert.True(CircleArc.TryCreate(new Vector(0, 0, 0), new Vector(10, 10, 0), new Vector(20, 0, 0), out CircleArc arc));

        Assert.True(arc.Center.IsSimilar(new Vector(10, 0, 0), 1e-9));
        Assert.Equal(10, arc.Radius, 9);
        Assert.Equal(Math.PI, arc.Sweep, 9);
        Assert.True(arc.Normal.IsSimilar(new Vector(0, 0, -1), 1e-9));
        Assert.True(arc.PointAt(0.5).IsSimilar(new Vector(10, 10, 0), 1e-9));
        Assert.True(arc.PointAt(1).IsSimilar(new Vector(20, 0, 0), 1e-9));
    }

    [Fact]
    public void TryCreate_ThreeQuarterTurn_SweepsThroughTheMiddlePoint()
    {
        // Start (10,0), through (-10,0), end (0,-10) on the unit-10 circle around the origin, counter-clockwise: 270 degrees.
        Assert.True(CircleArc.TryCreate(new Vector(10, 0, 3), new Vector(-10, 0, 3), new Vector(0, -10, 3), out CircleArc arc));

        Assert.Equal(1.5 * Math.PI, arc.Sweep, 9);
        Assert.Equal(15 * Math.PI, arc.Length, 9);
        Assert.True(arc.Normal.IsSimilar(new Vector(0, 0, 1), 1e-9));
        Assert.True(arc.PointAt(1.0 / 3).IsSimilar(new Vector(0, 10, 3), 1e-9));
    }

    [Fact]
    public void TryCreate_PointsOnALine_False()
    {
        Assert.False(CircleArc.TryCreate(new Vector(0, 0, 0), new Vector(1, 1, 1), new Vector(2, 2, 2), out _));
        Assert.False(CircleArc.TryCreate(new Vector(0, 0, 0), new Vector(0, 0, 0), new Vector(2, 2, 2), out _));
    }

    [Fact]
    public void SegmentCount_ChordTolerance_BoundsTheError()
    {
        Assert.True(CircleArc.TryCreate(new Vector(0, 0, 0), new Vector(10, 10, 0), new Vector(20, 0, 0), out CircleArc arc));

        int n = arc.SegmentCount(0.01);

        Assert.Equal(36, n);
        double sagitta = 10 * (1 - Math.Cos(Math.PI / n / 2));
        Assert.True(sagitta <= 0.01);
    }
}
