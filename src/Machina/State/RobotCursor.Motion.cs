using System.Runtime.CompilerServices;
namespace Machina;

internal sealed partial class RobotCursor
{
    private const string PoseUnknown =
        "the current position of the tool is not known yet; start with MoveTo, TransformTo or AxesTo before relative motions";

    private const string PoseUnknownAfterAxes =
        "the position of the tool after a joint motion (AxesTo) is not known without a robot model; give the robot its model " +
        "(Robot.Create(name, brand, model), or --model on the command line) or use MoveTo or TransformTo before relative motions";

    /// <summary>Why a relative motion cannot be applied now: no pose yet, or joints known but no model to turn them into a pose.</summary>
    private string PoseUnknownReason => (Axes is not null && Model is null ? PoseUnknownAfterAxes : PoseUnknown) + ".";

    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    private string? ApplyTranslation(ActionTranslation a)
    {
        if (a.Relative)
        {
            if (Position is not Vector pos || Rotation is not Rotation rot)
            {
                return PoseUnknownReason;
            }
            Vector offset = ReferenceCS == ReferenceCS.Local ? rot * a.Translation : a.Translation;
            return CommitCartesian(pos + offset, rot, offset.Length);
        }
        if (Rotation is not Rotation current)
        {
            return "the tool orientation is not known (the last motion was a joint motion); use TransformTo to give both position and orientation.";
        }
        return CommitCartesian(a.Translation, current, LineLength(a.Translation));
    }

    private string? ApplyRotation(ActionRotation a)
    {
        if (a.Relative)
        {
            if (Position is not Vector pos || Rotation is not Rotation rot)
            {
                return PoseUnknownReason;
            }
            Rotation next = ReferenceCS == ReferenceCS.Local ? rot * a.Rotation : a.Rotation * rot;
            return CommitCartesian(pos, next, 0);
        }
        if (Position is not Vector position)
        {
            return "the tool position is not known yet; use MoveTo or TransformTo first (RotateTo only turns the tool around its tip).";
        }
        return CommitCartesian(position, a.Rotation, 0);
    }

    private string? ApplyTransformation(ActionTransformation a)
    {
        if (!a.Relative)
        {
            return CommitCartesian(a.Translation, a.Rotation, LineLength(a.Translation));
        }
        if (Position is not Vector pos || Rotation is not Rotation rot)
        {
            return PoseUnknownReason;
        }
        Vector newPos;
        Rotation newRot;
        if (ReferenceCS == ReferenceCS.World)
        {
            newPos = pos + a.Translation;
            newRot = a.Rotation * rot;
        }
        else if (a.TranslationFirst)
        {
            newPos = pos + rot * a.Translation;
            newRot = rot * a.Rotation;
        }
        else
        {
            newRot = rot * a.Rotation;
            newPos = pos + newRot * a.Translation;
        }
        return CommitCartesian(newPos, newRot, Vector.Distance(pos, newPos));
    }

    private string? ApplyAxes(ActionAxes a)
    {
        Joints target;
        if (a.Relative)
        {
            if (Axes is not Joints current)
            {
                return "the joint angles are not known yet (the last motion was Cartesian); use AxesTo before relative Axes.";
            }
            target = current + a.Joints;
        }
        else
        {
            target = a.Joints;
        }
        if (!WithinReach(target))
        {
            return $"the joint angles would become [{string.Join(", ", target.ToArray().Select(Num.G))}] degrees; {JointLimitText}";
        }
        PrevPosition = Position;
        PrevRotation = Rotation;
        PrevAxes = Axes;
        Axes = target;
        Position = null;
        Rotation = null;
        LastPathLength = null;
        ArcThrough = null;
        ArcThroughRotation = null;
        UpdateExtrusion(null);
        return null;
    }

    private string? ApplyArc(ActionArcMotion a)
    {
        if (Position is not Vector start || Rotation is not Rotation rot)
        {
            return "an arc starts from the current position, which is not known yet; use MoveTo or TransformTo first.";
        }
        Vector through, end;
        Rotation throughRot, endRot;
        if (a.Relative)
        {
            bool local = ReferenceCS == ReferenceCS.Local;
            through = start + (local ? rot * a.Through.Origin : a.Through.Origin);
            end = start + (local ? rot * a.End.Origin : a.End.Origin);
            throughRot = endRot = rot;
        }
        else
        {
            through = a.Through.Origin;
            end = a.End.Origin;
            throughRot = a.PositionOnly ? rot : a.Through.Orientation;
            endRot = a.PositionOnly ? rot : a.End.Orientation;
        }
        if (!ArcGeometry.TryLength(start, through, end, out double length, out string? problem))
        {
            return problem;
        }
        if (!WithinReach(through))
        {
            return $"the arc's through point would be at {through} mm; {CoordinateLimitText}";
        }
        if (CommitCartesian(end, endRot, length) is string refusal)
        {
            return refusal;
        }
        ArcThrough = through;
        ArcThroughRotation = throughRot;
        return null;
    }

    /// <summary>
    /// The largest coordinate (mm) or joint value (degrees) a target may have: 1 km, or 2,777 turns. No robot or printer reaches
    /// beyond it, every brand's program and driver carries it, and a gantry of tens of metres stays far inside it.
    /// </summary>
    internal const double MaxCoordinate = 1_000_000;

    private const string CoordinateLimitText = "targets are refused beyond 1,000,000 mm (1 km) from the origin along X, Y or Z, which no robot or printer reaches.";

    private const string JointLimitText = "joint values are refused beyond 1,000,000 degrees (about 2,778 turns), which no robot reaches.";

    /// <summary>True when every coordinate is within <see cref="MaxCoordinate"/> (false for NaN and infinities).</summary>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    private static bool WithinReach(Vector v) => Within(v.X) && Within(v.Y) && Within(v.Z);

    private static bool WithinReach(Joints j) => Within(j.J1) && Within(j.J2) && Within(j.J3) && Within(j.J4) && Within(j.J5) && Within(j.J6);

    // Inlined: the optimised motion methods called it, unoptimised, three times a move until the runtime tiered it up.
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static bool Within(double value) => Math.Abs(value) <= MaxCoordinate;

    private double? LineLength(Vector target) => Position is Vector p ? Vector.Distance(p, target) : null;

    /// <summary>Makes a Cartesian motion the current pose, or refuses it (changing nothing) when a number would overflow.</summary>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    private string? CommitCartesian(Vector position, Rotation rotation, double? pathLength)
    {
        if (!WithinReach(position))
        {
            return $"the tool position would become {position} mm; {CoordinateLimitText}";
        }
        if (IsExtruding && pathLength is double length && !double.IsFinite(ExtrudedLength + ExtrusionRate * length))
        {
            return $"the extruded length would become too large to represent (extrusion rate {Num.G(ExtrusionRate)} mm/mm over {Num.G(length)} mm).";
        }
        PrevPosition = Position;
        PrevRotation = Rotation;
        // Joints and an arc's through point are mostly unknown already along a Cartesian toolpath: each check is one read of a
        // flag where the assignments wrote 56-, 32- and 48-byte structs on every move (the same values either way).
        if (Axes is not null || PrevAxes is not null)
        {
            PrevAxes = Axes;
            Axes = null;
        }
        Position = position;
        Rotation = rotation;
        LastPathLength = pathLength;
        if (ArcThrough is not null || ArcThroughRotation is not null)
        {
            ArcThrough = null;
            ArcThroughRotation = null;
        }
        UpdateExtrusion(pathLength);
        return null;
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)] // once a motion, from CommitCartesian: see Within
    private void UpdateExtrusion(double? pathLength)
    {
        PrevExtrudedLength = ExtrudedLength;
        if (!IsExtruding)
        {
            return;
        }
        if (pathLength is double length)
        {
            ExtrudedLength += ExtrusionRate * length;
        }
        else if (_applying is not null && Warn is not null)
        {
            Warn(_applying, "the extruded length could not be computed because the path length of this motion is unknown.");
        }
    }
}
