namespace Machina;

internal sealed partial class RobotCursor
{
    private const string PoseUnknown =
        "the current position of the tool is not known yet; start with MoveTo, TransformTo or AxesTo before relative motions";

    private string? ApplyTranslation(ActionTranslation a)
    {
        if (a.Relative)
        {
            if (Position is not Vector pos || Rotation is not Rotation rot)
            {
                return PoseUnknown + ".";
            }
            Vector offset = ReferenceCS == ReferenceCS.Local ? rot * a.Translation : a.Translation;
            CommitCartesian(pos + offset, rot, offset.Length);
            return null;
        }
        if (Rotation is not Rotation current)
        {
            return "the tool orientation is not known (the last motion was a joint motion); use TransformTo to give both position and orientation.";
        }
        CommitCartesian(a.Translation, current, LineLength(a.Translation));
        return null;
    }

    private string? ApplyRotation(ActionRotation a)
    {
        if (a.Relative)
        {
            if (Position is not Vector pos || Rotation is not Rotation rot)
            {
                return PoseUnknown + ".";
            }
            Rotation next = ReferenceCS == ReferenceCS.Local ? rot * a.Rotation : a.Rotation * rot;
            CommitCartesian(pos, next, 0);
            return null;
        }
        if (Position is not Vector position)
        {
            return "the tool position is not known yet; use MoveTo or TransformTo first (RotateTo only turns the tool around its tip).";
        }
        CommitCartesian(position, a.Rotation, 0);
        return null;
    }

    private string? ApplyTransformation(ActionTransformation a)
    {
        if (!a.Relative)
        {
            CommitCartesian(a.Translation, a.Rotation, LineLength(a.Translation));
            return null;
        }
        if (Position is not Vector pos || Rotation is not Rotation rot)
        {
            return PoseUnknown + ".";
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
        CommitCartesian(newPos, newRot, Vector.Distance(pos, newPos));
        return null;
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
        CommitCartesian(end, endRot, length);
        ArcThrough = through;
        ArcThroughRotation = throughRot;
        return null;
    }

    private double? LineLength(Vector target) => Position is Vector p ? Vector.Distance(p, target) : null;

    private void CommitCartesian(Vector position, Rotation rotation, double? pathLength)
    {
        PrevPosition = Position;
        PrevRotation = Rotation;
        PrevAxes = Axes;
        Position = position;
        Rotation = rotation;
        Axes = null;
        LastPathLength = pathLength;
        ArcThrough = null;
        ArcThroughRotation = null;
        UpdateExtrusion(pathLength);
    }

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
