namespace Machina.Tests.Conventions;

/// <summary>
/// Members of the original that still compile against ours but give different results: the comparison can't see these, so
/// they are listed by hand (original listing line → what differs). Each one is "changed" in docs/migrating.md.
/// </summary>
internal static class OriginalMeaningChanges
{
    private const string G = "Machina.Types.Geometry.";

    public static readonly IReadOnlyDictionary<string, string> All = new Dictionary<string, string>(StringComparer.Ordinal)
    {
        [$"{G}Rotation.Angle {{ get; }} -> double"] =
            "same name, canonical value: the angle is in [0°, 180°] (with `Axis` flipped to match); the original returned the angle as given (−90 stayed −90, 450 stayed 450). The rotation is the same.",
        [$"{G}Rotation.Axis {{ get; }} -> {G}Vector"] =
            "same name, canonical value: the unit axis that goes with an angle in [0°, 180°] (`new Rotation(0, 0, 1, -90).Axis` is (0, 0, −1) here, (0, 0, 1) in the original).",
        [$"{G}Vector.Equals({G}Vector other) -> bool"] =
            "exact comparison here (as `==`); the original allowed 1e-6 per component: use `a.IsSimilar(b)`.",
        [$"override {G}Vector.Equals(object obj) -> bool"] =
            "exact comparison here; the original allowed 1e-6 per component: use `a.IsSimilar(b)`.",
        [$"{G}Quaternion.Quaternion(double w, double x, double y, double z)"] =
            "keeps the four numbers as given; the original rescaled the vector part to make a unit quaternion ((0.5, 2, 0, 0) became (0.5, 0.866, 0, 0)). `ToRotation()` scales to unit length.",
        [$"{G}Quaternion.IsEquivalent({G}Quaternion other) -> bool"] =
            "a correct test here (|q1·q2| ≈ 1 after normalising); the original compared sums of components and could say true for different rotations.",
        [$"{G}Quaternion.ToAxisAngle() -> {G}AxisAngle"] =
            "angle in [0°, 180°] here; the original gave (0°, 360°] (an angle over 180° when W < 0). Same rotation.",
        [$"{G}Quaternion.ToRotationVector(bool radians) -> {G}RotationVector"] =
            "the vector of the [0°, 180°] axis-angle; the original's could be longer than 180° when W < 0. Same rotation.",
        [$"static {G}Quaternion.Scale({G}Quaternion q, double factor) -> {G}Quaternion"] =
            "returns the scaled quaternion; the original returned an unscaled copy and scaled its argument instead (a bug).",
        [$"{G}AxisAngle.AxisAngle({G}Vector axis, double angleDegs)"] =
            "keeps the axis as given; the original scaled it to unit length. `ToRotation()` and the conversions accept any non-zero axis; use `axis.Normalized()` if you read `Axis` back.",
        [$"override {G}Point.ToString() -> string"] =
            "the text is `[400, 300, 500]`, with spaces, as every position Machina writes for people (`Vector`, the log, the events); the original wrote `[400,300,500]`.",
        [$"{G}AxisAngle.Axis {{ get; }} -> {G}Vector"] =
            "the axis as given to the constructor (not normalised, unlike the original).",
    };
}
