using System.Globalization;

namespace Machina.Benchmarks;

/// <summary>
/// The kinds of instruction files the cold-compile scenarios read (issue 45): the mixed program the other scenarios use, and
/// three that users write in bulk, since a figure for one shape does not carry over to another.
/// </summary>
internal enum InputShape
{
    /// <summary>Relative moves with speed changes, waits, messages, comments, rotations and absolute moves mixed in.</summary>
    Mixed,

    /// <summary>Only absolute moves (<c>MoveTo</c>), as a path exported from CAD writes them.</summary>
    Absolute,

    /// <summary>Only small relative moves (<c>Move(±0.x, ±0.x, 0.001)</c>), as a slicer writes them.</summary>
    Small,

    /// <summary>Relative rotations and moves taking turns.</summary>
    Rotations,
}

/// <summary>Writes the lines of each <see cref="InputShape"/>.</summary>
internal static class InputShapes
{
    /// <summary>The suffix a scenario's name gets for <paramref name="shape"/> (none for the mixed program).</summary>
    public static string Suffix(InputShape shape) => shape == InputShape.Mixed ? "" : "-" + shape.ToString().ToLowerInvariant();

    /// <summary>Line <paramref name="i"/> (from 1; line 0 is the absolute start) of a file of <paramref name="shape"/>.</summary>
    public static string Line(InputShape shape, int i, Random random)
    {
        string F(double value) => Math.Round(value, 3).ToString("0.###", CultureInfo.InvariantCulture);
        double Signed(double scale) => (random.NextDouble() - 0.5) * scale;
        return shape switch
        {
            InputShape.Absolute => $"MoveTo({F(300 + Signed(200))}, {F(Signed(200))}, {F(500 + Signed(200))});",
            InputShape.Small => $"Move({F(Signed(1.6))}, {F(Signed(1.6))}, 0.001);",
            InputShape.Rotations => i % 2 == 0
                ? $"Rotate(0, 0, 1, {F(Signed(4))});"
                : $"Move({F(Signed(4))}, {F(Signed(4))}, {F(Signed(0.4))});",
            _ => Workloads.Line(i, random),
        };
    }
}
