namespace Machina;

/// <summary>Moves the tool tip along a circular arc that passes through one point and ends at another.</summary>
public sealed record ActionArcMotion : RobotAction
{
    /// <summary>Creates an arc; positions in mm. With <paramref name="positionOnly"/> the tool keeps its orientation and only the plane origins count.</summary>
    public ActionArcMotion(Plane through, Plane end, bool relative, bool positionOnly)
    {
        through.Origin.RequireFinite(nameof(through));
        end.Origin.RequireFinite(nameof(end));
        if (relative && !positionOnly)
        {
            throw new ArgumentException("A relative arc can only give positions; use ArcMotionTo with planes for an arc that also rotates the tool.", nameof(relative));
        }
        Through = positionOnly ? new Plane(through.Origin, Rotation.Identity) : through;
        End = positionOnly ? new Plane(end.Origin, Rotation.Identity) : end;
        Relative = relative;
        PositionOnly = positionOnly;
    }

    /// <summary>A point (and orientation, unless position-only) the arc passes through, mm.</summary>
    public Plane Through { get; }

    /// <summary>The end point (and orientation, unless position-only) of the arc, mm.</summary>
    public Plane End { get; }

    /// <summary>True when the points are offsets from the current position.</summary>
    public bool Relative { get; }

    /// <summary>True when the arc only moves the tool tip and keeps its orientation.</summary>
    public bool PositionOnly { get; }

    /// <inheritdoc/>
    public override bool IsRelative => Relative;

    /// <inheritdoc/>
    public override ActionType Type => ActionType.ArcMotion;

    /// <inheritdoc/>
    public override string ToInstruction()
    {
        Vector t = Through.Origin, e = End.Origin;
        if (PositionOnly)
        {
            return InstructionText.Call(Relative ? "ArcMotion" : "ArcMotionTo", t.X, t.Y, t.Z, e.X, e.Y, e.Z);
        }
        Vector tx = InstructionText.Axis(Through.XAxis), ty = InstructionText.Axis(Through.YAxis);
        Vector ex = InstructionText.Axis(End.XAxis), ey = InstructionText.Axis(End.YAxis);
        return InstructionText.Call("ArcMotionTo",
            t.X, t.Y, t.Z, tx.X, tx.Y, tx.Z, ty.X, ty.Y, ty.Z,
            e.X, e.Y, e.Z, ex.X, ex.Y, ex.Z, ey.X, ey.Y, ey.Z);
    }

    /// <inheritdoc/>
    public override string Describe()
    {
        string kind = Relative ? "Relative arc" : "Arc";
        if (PositionOnly)
        {
            return $"{kind} motion through {(Point)Through.Origin} to {(Point)End.Origin}";
        }
        return $"{kind} motion through {(Point)Through.Origin} {Through.Orientation.ToOrientationString()} to {(Point)End.Origin} {End.Orientation.ToOrientationString()}";
    }

    /// <summary>Equal when flags and points agree exactly and orientations within 1e-9 degrees.</summary>
    public bool Equals(ActionArcMotion? other) =>
        other is not null && Relative == other.Relative && PositionOnly == other.PositionOnly
        && Through.Origin == other.Through.Origin && End.Origin == other.End.Origin
        && Through.Orientation.IsSimilar(other.Through.Orientation, 1e-9) && End.Orientation.IsSimilar(other.End.Orientation, 1e-9);

    /// <inheritdoc/>
    public override int GetHashCode() => HashCode.Combine(Type, Relative, Through.Origin, End.Origin);
}
