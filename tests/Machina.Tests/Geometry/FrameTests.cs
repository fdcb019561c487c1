namespace Machina.Tests.Geometry;

public class FrameTests
{
    [Theory]
    [InlineData(1, 1, 0, 1, -1, 0, "[0, 0.9239, 0.3827, 0]", "[[0.707, 0.707, 0], [0.707, -0.707, 0], [0, 0, -1]]")]
    [InlineData(-1, 0, 0, 0, 0, -1, "[0, 0, -0.7071, 0.7071]", "[[-1, 0, 0], [0, 0, -1], [0, -1, 0]]")]
    [InlineData(-1, 0, 0, 0, 1, 0, "[0, 0, 1, 0]", "[[-1, 0, 0], [0, 1, 0], [0, 0, -1]]")]
    [InlineData(1, 0, 0, 0, 1, 0, "[1, 0, 0, 0]", "[[1, 0, 0], [0, 1, 0], [0, 0, 1]]")]
    public void Orientation_FromAxes_SpecExamples(double x0, double x1, double x2, double y0, double y1, double y2, string quaternion, string axes)
    {
        var o = new Orientation(x0, x1, x2, y0, y1, y2);
        Assert.Equal(quaternion, o.Rotation.ToQuaternionString());
        Assert.Equal(axes, o.ToString());
        Assert.Equal(o, new Orientation(new Vector(x0, x1, x2), new Vector(y0, y1, y2)));
    }

    [Fact]
    public void Orientation_NonOrthogonalY_ReorthogonalisedRightHanded()
    {
        var o = new Orientation(new Vector(0, 0, 3), new Vector(1, 0, 1));
        Oracle.SameVector(Vector.ZAxis, o.XAxis, 1e-15);
        Oracle.SameVector(Vector.XAxis, o.YAxis, 1e-15);
        Oracle.SameVector(Vector.YAxis, o.ZAxis, 1e-15);
        Assert.Equal(1, Vector.Dot(Vector.Cross(o.XAxis, o.YAxis), o.ZAxis), 14);
    }

    [Fact]
    public void Orientation_ParallelOrZeroAxes_ThrowsArgumentException()
    {
        Assert.Throws<ArgumentException>(() => new Orientation(1, 0, 0, 2, 0, 0));
        Assert.Throws<ArgumentException>(() => new Orientation(1, 0, 0, -1, 0, 0));
        Assert.Throws<ArgumentException>(() => new Orientation(Vector.Zero, Vector.YAxis));
    }

    [Fact]
    public void Orientation_ImplicitConversions_SameRotation()
    {
        Rotation r = Rotation.FromAxisAngle(Vector.ZAxis, 30);
        Orientation o = r;
        Rotation back = o;
        Assert.Equal(r, back);
        Assert.Equal(Rotation.Identity, Orientation.WorldXY.Rotation);
        Assert.True(o == new Orientation(r));
        Assert.False(o != new Orientation(r));
    }

    [Fact]
    public void Plane_FromAxes_OriginAndAxes()
    {
        var p = new Plane(100, 200, 300, 0, 1, 0, -1, 0, 0);
        Assert.Equal(new Vector(100, 200, 300), p.Origin);
        Oracle.SameVector(Vector.YAxis, p.XAxis, 1e-15);
        Oracle.SameVector(-Vector.XAxis, p.YAxis, 1e-15);
        Oracle.SameVector(Vector.ZAxis, p.ZAxis, 1e-15);
        Oracle.SameRotation(Rotation.FromAxisAngle(Vector.ZAxis, 90), p.Orientation, 1e-12);
        Assert.Equal("Plane[[100, 200, 300], [[0, 1, 0], [-1, 0, 0], [0, 0, 1]]]", p.ToString());
        Assert.Equal(p, new Plane(new Vector(100, 200, 300), Vector.YAxis, -Vector.XAxis));
    }

    [Fact]
    public void Plane_Default_WorldXYAtOrigin()
    {
        Assert.Equal("Plane[[0, 0, 0], [[1, 0, 0], [0, 1, 0], [0, 0, 1]]]", Plane.WorldXY.ToString());
        Assert.Equal(Vector.ZAxis, default(Plane).ZAxis);
        Assert.Throws<ArgumentException>(() => new Plane(Vector.Zero, Vector.XAxis, Vector.XAxis));
    }
}
