namespace Machina;

/// <summary>A frame in space: an origin in millimetres and an orientation. <c>default</c> is the world XY frame at the origin.</summary>
/// <param name="Origin">Origin of the frame (mm).</param>
/// <param name="Orientation">Orientation of the frame.</param>
public readonly record struct Plane(Vector Origin, Rotation Orientation)
{
    /// <summary>A frame from an origin and its X and Y axis directions.</summary>
    public Plane(Vector origin, Vector xAxis, Vector yAxis) : this(origin, Rotation.FromAxes(xAxis, yAxis)) { }

    /// <summary>A frame from origin (ox, oy, oz), X axis (xx, xy, xz) and Y axis (yx, yy, yz).</summary>
    public Plane(double ox, double oy, double oz, double xx, double xy, double xz, double yx, double yy, double yz)
        : this(new Vector(ox, oy, oz), Rotation.FromAxes(new Vector(xx, xy, xz), new Vector(yx, yy, yz))) { }

    /// <summary>The world XY frame at the origin.</summary>
    public static Plane WorldXY => default;

    /// <summary>X axis of the frame.</summary>
    public Vector XAxis => Orientation.XAxis;

    /// <summary>Y axis of the frame.</summary>
    public Vector YAxis => Orientation.YAxis;

    /// <summary>Z axis (normal) of the frame.</summary>
    public Vector ZAxis => Orientation.ZAxis;

    /// <summary>Text such as <c>Plane[[0, 0, 0], [[1, 0, 0], [0, 1, 0], [0, 0, 1]]]</c>.</summary>
    public override string ToString() => $"Plane[{Origin}, {Orientation.ToOrientationString()}]";
}
