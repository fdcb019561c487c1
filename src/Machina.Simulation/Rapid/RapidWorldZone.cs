namespace Machina.Simulation.Rapid;

/// <summary>
/// A <c>shapedata</c> (RAPID World Zones): a box between two corners, a cylinder standing on its centre point (its height along the
/// world z axis, downwards when negative) or a sphere, in world coordinates (mm); or a joint space (WZLimJointDef, WZHomeJointDef):
/// each robot axis between a low and a high angle, an axis given as 9E9 not supervised. The zone is its inside, or with \Outside the rest.
/// </summary>
internal sealed class RapidShape
{
    /// <summary>"box", "cylinder", "sphere" or "joints"; null until WZBoxDef, WZCylDef, WZSphDef, WZLimJointDef or WZHomeJointDef defined it.</summary>
    public string? Kind { get; private set; }

    /// <summary>True when the zone is outside the shape (\Outside).</summary>
    public bool Outside { get; private set; }

    /// <summary>A joint value at or beyond it (9E9) leaves its axis out of a joint space.</summary>
    private const double Unsupervised = 9E8;

    private Vector _a, _b;
    private double _radius, _height;
    private double[] _low = [], _high = [];

    /// <summary>WZBoxDef: the box between <paramref name="low"/> and <paramref name="high"/>.</summary>
    public void Box(bool outside, Vector low, Vector high) => (Kind, Outside, _a, _b) = ("box", outside, low, high);

    /// <summary>WZCylDef.</summary>
    public void Cylinder(bool outside, Vector centre, double radius, double height) => (Kind, Outside, _a, _radius, _height) = ("cylinder", outside, centre, radius, height);

    /// <summary>WZSphDef.</summary>
    public void Sphere(bool outside, Vector centre, double radius) => (Kind, Outside, _a, _radius) = ("sphere", outside, centre, radius);

    /// <summary>WZLimJointDef, WZHomeJointDef: the robot axes between <paramref name="low"/> and <paramref name="high"/> (degrees; 9E9: not supervised).</summary>
    public void JointSpace(bool outside, double[] low, double[] high) => (Kind, Outside, _low, _high) = ("joints", outside, low, high);

    /// <summary>A copy (a zone keeps the shape it was activated with).</summary>
    public RapidShape Copy() => (RapidShape)MemberwiseClone();

    /// <summary>True when the TCP at <paramref name="p"/> (world, mm), with the arm at <paramref name="joints"/>, is in the zone.</summary>
    public bool Contains(Vector p, Joints joints)
    {
        bool inShape = Kind switch
        {
            "joints" => InJointSpace(joints.ToArray()),
            "box" => p.X >= _a.X && p.X <= _b.X && p.Y >= _a.Y && p.Y <= _b.Y && p.Z >= _a.Z && p.Z <= _b.Z,
            "cylinder" => Square(p.X - _a.X) + Square(p.Y - _a.Y) <= _radius * _radius
                && p.Z >= Math.Min(_a.Z, _a.Z + _height) && p.Z <= Math.Max(_a.Z, _a.Z + _height),
            "sphere" => (p - _a).Length <= _radius,
            _ => false,
        };
        return Kind is not null && inShape != Outside;
    }

    private bool InJointSpace(double[] j) => Enumerable.Range(0, Math.Min(j.Length, _low.Length))
        .All(i => Math.Abs(_low[i]) >= Unsupervised || Math.Abs(_high[i]) >= Unsupervised || (j[i] >= _low[i] && j[i] <= _high[i]));

    private static double Square(double x) => x * x;
}

/// <summary>
/// A <c>wzstationary</c> or <c>wztemporary</c>: a world zone that WZLimSup or WZDOSet made active on the controller. A limit zone
/// (WZLimSup) refuses motion that would take the TCP into it; an output zone (WZDOSet) keeps a digital output at its value while
/// the TCP is in it and at the other value while it is not.
/// </summary>
internal sealed class RapidWorldZone
{
    /// <summary>The zone's shape (a copy made when it was activated), or null before.</summary>
    public RapidShape? Shape { get; set; }

    /// <summary>True for WZLimSup, false for WZDOSet.</summary>
    public bool Limits { get; set; }

    /// <summary>The output of a WZDOSet zone: its name, index, and the value while the TCP is inside.</summary>
    public (string Name, int Index, bool Inside)? Output { get; set; }

    /// <summary>False for a temporary zone after WZDisable (WZEnable makes it active again).</summary>
    public bool Enabled { get; set; } = true;

    /// <summary>True for a stationary zone (\Stat), false for a temporary one (\Temp).</summary>
    public bool Stationary { get; set; }

    /// <summary>The program line that activated it, for messages.</summary>
    public int Line { get; set; }
}
