using System.Runtime.CompilerServices;

namespace Machina;

public sealed partial class Robot
{
    /// <summary>Moves the tool tip by an offset in mm (in the world frame, or the tool's frame after <c>Coordinates("Local")</c>).</summary>
    // AggressiveOptimization on the four moves of a script's loop, on Issue and on the action's constructor: a fresh process
    // issues 10^5 moves before the runtime has optimised these (it did so only after the loop had ended), so each move ran
    // them, and the small property getters they call, as unoptimised first-tier code (docs/performance.md, session 26).
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    public bool Move(Vector direction) => Issue(new ActionTranslation(Arg.Finite(direction), true));

    /// <summary>Moves the tool tip by (x, y, z) mm.</summary>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    public bool Move(double incX, double incY, double incZ = 0) => Issue(new ActionTranslation(Arg.Vector(incX, incY, incZ), true));

    /// <summary>Moves the tool tip to a position in mm, keeping its orientation.</summary>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    public bool MoveTo(Vector position) => Issue(new ActionTranslation(Arg.Finite(position), false));

    /// <summary>Moves the tool tip to (x, y, z) mm, keeping its orientation.</summary>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    public bool MoveTo(double x, double y, double z) => Issue(new ActionTranslation(Arg.Vector(x, y, z), false));

    /// <summary>Rotates the tool around its tip by a rotation.</summary>
    public bool Rotate(Rotation rotation) => Issue(new ActionRotation(rotation, true));

    /// <summary>Rotates the tool around its tip by <paramref name="angleDegrees"/> around an axis (right-hand rule).</summary>
    public bool Rotate(Vector axis, double angleDegrees) => Issue(new ActionRotation(axis, Arg.Finite(angleDegrees), true));

    /// <summary>Rotates the tool around its tip by <paramref name="angleDegrees"/> around the axis (x, y, z).</summary>
    public bool Rotate(double rotVecX, double rotVecY, double rotVecZ, double angleDegrees) =>
        Issue(Arg.Renamed("axis", nameof(rotVecX), (Arg.Vector(rotVecX, rotVecY, rotVecZ), Arg.Finite(angleDegrees)), static a => new ActionRotation(a.Item1, a.Item2, true)));

    /// <summary>Turns the tool to an orientation, keeping its tip in place.</summary>
    public bool RotateTo(Rotation rotation) => Issue(new ActionRotation(rotation, false));

    /// <summary>Turns the tool to an orientation, keeping its tip in place.</summary>
    public bool RotateTo(Orientation orientation) => Issue(new ActionRotation(orientation.Rotation, false));

    /// <summary>Turns the tool so that its X and Y axes point along the given directions.</summary>
    public bool RotateTo(Vector xAxis, Vector yAxis) => Issue(new ActionRotation(Arg.FromAxes(xAxis, yAxis, nameof(xAxis), nameof(yAxis)), false));

    /// <summary>Turns the tool so that its X axis is (x0, x1, x2) and its Y axis is (y0, y1, y2).</summary>
    public bool RotateTo(double x0, double x1, double x2, double y0, double y1, double y2) =>
        Issue(new ActionRotation(Arg.FromAxes(Arg.Vector(x0, x1, x2), Arg.Vector(y0, y1, y2), nameof(x0), nameof(y0)), false));

    /// <summary>Moves by an offset (mm), then rotates.</summary>
    public bool Transform(Vector direction, Rotation rotation) => Issue(new ActionTransformation(Arg.Finite(direction), rotation, true, true));

    /// <summary>Rotates, then moves by an offset (mm); the difference shows in the tool's frame.</summary>
    public bool Transform(Rotation rotation, Vector direction) => Issue(new ActionTransformation(Arg.Finite(direction), rotation, true, false));

    /// <summary>Moves to a position (mm) and orientation in one motion.</summary>
    public bool TransformTo(Vector position, Rotation orientation) => Issue(new ActionTransformation(Arg.Finite(position), orientation, false, true));

    /// <summary>Moves to a position (mm) and orientation in one motion.</summary>
    public bool TransformTo(Rotation orientation, Vector position) => Issue(new ActionTransformation(Arg.Finite(position), orientation, false, false));

    /// <summary>Moves the tool tip to (x, y, z) mm with its X axis along (x0, x1, x2) and Y axis along (y0, y1, y2).</summary>
    public bool TransformTo(double x, double y, double z, double x0, double x1, double x2, double y0, double y1, double y2) =>
        Issue(new ActionTransformation(Arg.Vector(x, y, z), Arg.FromAxes(Arg.Vector(x0, x1, x2), Arg.Vector(y0, y1, y2), nameof(x0), nameof(y0)), false, true));

    /// <summary>Moves along a circular arc through a point to an end point, both given as offsets (mm) from the current position.</summary>
    public bool ArcMotion(Vector through, Vector end) =>
        Issue(new ActionArcMotion(new Plane(through, Rotation.Identity), new Plane(end, Rotation.Identity), true, true));

    /// <summary>Moves along a circular arc through (tx, ty, tz) to (ex, ey, ez), both offsets in mm from the current position.</summary>
    public bool ArcMotion(double throughX, double throughY, double throughZ, double endX, double endY, double endZ) =>
        ArcMotion(Arg.Vector(throughX, throughY, throughZ), Arg.Vector(endX, endY, endZ));

    /// <summary>Moves along a circular arc through a point to an end point (mm), keeping the tool orientation.</summary>
    public bool ArcMotionTo(Vector through, Vector end) =>
        Issue(new ActionArcMotion(new Plane(through, Rotation.Identity), new Plane(end, Rotation.Identity), false, true));

    /// <summary>Moves along a circular arc through (tx, ty, tz) to (ex, ey, ez) mm, keeping the tool orientation.</summary>
    public bool ArcMotionTo(double throughX, double throughY, double throughZ, double endX, double endY, double endZ) =>
        ArcMotionTo(Arg.Vector(throughX, throughY, throughZ), Arg.Vector(endX, endY, endZ));

    /// <summary>Moves along a circular arc through one frame to another, turning the tool to each frame's orientation.</summary>
    public bool ArcMotionTo(Plane through, Plane end) => Issue(new ActionArcMotion(through, end, false, false));

    /// <summary>
    /// Moves along a circular arc through one frame to another, given as 18 numbers: the through frame's origin (mm), X axis and
    /// Y axis, then the end frame's origin (mm), X axis and Y axis. The tool turns to each frame's orientation.
    /// </summary>
    public bool ArcMotionTo(
        double throughX, double throughY, double throughZ, double throughXAxisX, double throughXAxisY, double throughXAxisZ,
        double throughYAxisX, double throughYAxisY, double throughYAxisZ,
        double endX, double endY, double endZ, double endXAxisX, double endXAxisY, double endXAxisZ,
        double endYAxisX, double endYAxisY, double endYAxisZ) =>
        ArcMotionTo(
            new Plane(Arg.Vector(throughX, throughY, throughZ),
                Arg.FromAxes(Arg.Vector(throughXAxisX, throughXAxisY, throughXAxisZ), Arg.Vector(throughYAxisX, throughYAxisY, throughYAxisZ), nameof(throughXAxisX), nameof(throughYAxisX))),
            new Plane(Arg.Vector(endX, endY, endZ),
                Arg.FromAxes(Arg.Vector(endXAxisX, endXAxisY, endXAxisZ), Arg.Vector(endYAxisX, endYAxisY, endYAxisZ), nameof(endXAxisX), nameof(endYAxisX))));

    /// <summary>Turns the joints by the given amounts, degrees.</summary>
    public bool Axes(Joints increments) => Issue(new ActionAxes(increments.RequireFinite(nameof(increments)), true));

    /// <summary>Turns the joints by the given amounts, degrees.</summary>
    public bool Axes(double incJ1, double incJ2, double incJ3, double incJ4, double incJ5, double incJ6) =>
        Issue(new ActionAxes(new Joints(Arg.Finite(incJ1), Arg.Finite(incJ2), Arg.Finite(incJ3), Arg.Finite(incJ4), Arg.Finite(incJ5), Arg.Finite(incJ6)), true));

    /// <summary>Turns the joints to the given angles, degrees.</summary>
    public bool AxesTo(Joints joints) => Issue(new ActionAxes(joints, false));

    /// <summary>Turns the joints to the given angles, degrees.</summary>
    public bool AxesTo(double j1, double j2, double j3, double j4, double j5, double j6) =>
        Issue(new ActionAxes(new Joints(Arg.Finite(j1), Arg.Finite(j2), Arg.Finite(j3), Arg.Finite(j4), Arg.Finite(j5), Arg.Finite(j6)), false));

    /// <summary>Changes external axis 1..6 (track or positioner) by an amount, mm or degrees.</summary>
    public bool ExternalAxis(int axisNumber, double increment, ExternalAxesTarget target = ExternalAxesTarget.All) =>
        Issue(new ActionExternalAxis(axisNumber, Arg.Finite(increment), target, true));

    /// <summary>Changes external axis 1..6 by an amount; <paramref name="target"/> is "All", "Cartesian" or "Joint".</summary>
    public bool ExternalAxis(int axisNumber, double increment, string target) =>
        ExternalAxis(axisNumber, increment, EnumText.Parse<ExternalAxesTarget>(target, "external axes target", nameof(target)));

    /// <summary>Sets external axis 1..6 (track or positioner) to a value, mm or degrees.</summary>
    public bool ExternalAxisTo(int axisNumber, double value, ExternalAxesTarget target = ExternalAxesTarget.All) =>
        Issue(new ActionExternalAxis(axisNumber, value, target, false));

    /// <summary>Sets external axis 1..6 to a value; <paramref name="target"/> is "All", "Cartesian" or "Joint".</summary>
    public bool ExternalAxisTo(int axisNumber, double value, string target) =>
        ExternalAxisTo(axisNumber, value, EnumText.Parse<ExternalAxesTarget>(target, "external axes target", nameof(target)));

    /// <summary>Changes the arm angle of a 7-axis arm, degrees.</summary>
    public bool ArmAngle(double increment) => Issue(new ActionArmAngle(Arg.Finite(increment), true));

    /// <summary>Sets the arm angle of a 7-axis arm, degrees.</summary>
    public bool ArmAngleTo(double angle) => Issue(new ActionArmAngle(angle, false));
}
