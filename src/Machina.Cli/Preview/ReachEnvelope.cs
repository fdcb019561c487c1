namespace Machina.Cli.Preview;

/// <summary>
/// Where an arm's flange can get, as the views see it: the outline of every flange position the joints reach within their
/// limits (axis 1 turned all the way round), seen from the front or the side (<see cref="Outline"/>, radius and height) and
/// from above (a circle of <see cref="Radius"/>). Outside the outline the flange cannot get; inside, it may need another
/// orientation. Found by sampling the joints, so the line may pass inside the true edge by up to about 2 % of the reach.
/// </summary>
internal sealed class ReachEnvelope
{
    /// <summary>Angular steps around the shoulder for the outline.</summary>
    internal const int Directions = 180;

    /// <summary>Samples of axes 2 and 3, and of axes 4 and 5 (the wrist; axis 6 only turns the flange).</summary>
    internal const int Samples = 48, WristSamples = 7;

    private ReachEnvelope(IReadOnlyList<(double R, double Z)> outline, double radius, double radiusHeight)
    {
        Outline = outline;
        Radius = radius;
        RadiusHeight = radiusHeight;
    }

    /// <summary>The closed outline in the plane of axis 1, as (horizontal distance from the base axis, signed; height) in mm, the first point repeated last.</summary>
    internal IReadOnlyList<(double R, double Z)> Outline { get; }

    /// <summary>The farthest the flange gets from the base axis, mm (the circle of the top view).</summary>
    internal double Radius { get; }

    /// <summary>The height at which it gets that far, mm.</summary>
    internal double RadiusHeight { get; }

    /// <summary>The envelope of <paramref name="model"/>.</summary>
    internal static ReachEnvelope Of(RobotModel model)
    {
        var points = new List<(double R, double Z)>(Samples * Samples * WristSamples * WristSamples * 2);
        double Step(int axis, int i, int count) => model.MinJoints[axis] + ((model.MaxJoints[axis] - model.MinJoints[axis]) * i / (count - 1));
        for (int i = 0; i < Samples; i++)
        {
            for (int j = 0; j < Samples; j++)
            {
                for (int k = 0; k < WristSamples; k++)
                {
                    for (int m = 0; m < WristSamples; m++)
                    {
                        Vector p = model.Kinematics.Forward(new Joints(0, Step(1, i, Samples), Step(2, j, Samples), Step(3, k, WristSamples), Step(4, m, WristSamples), 0)).Position;
                        double r = Math.Sqrt((p.X * p.X) + (p.Y * p.Y));
                        points.Add((r, p.Z));
                        points.Add((-r, p.Z)); // axis 1 turned half round
                    }
                }
            }
        }
        double centreZ = model.LinkPositions(new Joints(0, 0, 0, 0, 0, 0)).Skip(1).FirstOrDefault().Z;
        var farthest = new (double R, double Z, double D)?[Directions];
        foreach ((double r, double z) in points)
        {
            double angle = Math.Atan2(z - centreZ, r);
            int bin = Math.Clamp((int)Math.Floor((angle + Math.PI) / (2 * Math.PI) * Directions), 0, Directions - 1);
            double d = (r * r) + ((z - centreZ) * (z - centreZ));
            if (farthest[bin] is not { } best || d > best.D)
            {
                farthest[bin] = (r, z, d);
            }
        }
        List<(double R, double Z)> outline = [.. farthest.Where(f => f is not null).Select(f => (f!.Value.R, f.Value.Z))];
        outline.Add(outline[0]);
        (double R, double Z) widest = points.MaxBy(p => p.R);
        return new ReachEnvelope(outline, widest.R, widest.Z);
    }

    /// <summary>The outline in the vertical plane at <paramref name="degrees"/> around the base axis (0: the XZ plane, 90: the YZ plane).</summary>
    internal IReadOnlyList<Vector> InPlane(double degrees)
    {
        double c = Math.Cos(degrees * Math.PI / 180), s = Math.Sin(degrees * Math.PI / 180);
        return [.. Outline.Select(p => new Vector(p.R * c, p.R * s, p.Z))];
    }

    /// <summary>The circle of <see cref="Radius"/> at height <paramref name="z"/>, in <paramref name="segments"/> pieces, closed.</summary>
    internal IReadOnlyList<Vector> Circle(double z, int segments = 96) =>
        [.. Enumerable.Range(0, segments + 1).Select(i => new Vector(Radius * Math.Cos(2 * Math.PI * i / segments), Radius * Math.Sin(2 * Math.PI * i / segments), z))];
}
