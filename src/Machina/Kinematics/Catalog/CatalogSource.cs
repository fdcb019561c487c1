namespace Machina;

/// <summary>Shared helpers for the catalogue files: short constructors and the citation text of each public description.</summary>
internal static class CatalogSource
{
    internal static Joints J(double a, double b, double c, double d, double e, double f) => new(a, b, c, d, e, f);

    /// <summary>An ABB or KUKA arm from its OPW lengths (mm, b = 0), joint ranges (°) and maximum joint speeds (°/s).</summary>
    internal static RobotModel Opw(string brand, string name, double a1, double a2, double c1, double c2, double c3, double c4,
        Joints min, Joints max, Joints? speeds, string source) =>
        RobotModel.FromOpw(name, brand, new OpwParameters(a1, a2, 0, c1, c2, c3, c4), min, max, speeds, source);

    /// <summary>
    /// Citation of a file in a public robot description, with what was taken from it. Lengths are the file's joint origins converted
    /// to OPW, ranges its joint limits (rounded to 0.5°, the files store radians with four digits), speeds its velocity limits (rad/s → °/s).
    /// </summary>
    internal static string Cite(string repository, string path, string? note) =>
        $"{repository}, {path}: joint origins, limits and velocities{(note is null ? "" : $"; {note}")}";
}
