namespace Machina;

/// <summary>
/// Equality to the last bit (<c>-0</c> differs from <c>0</c>, a NaN equals the same NaN): what a kept result may be reused for,
/// since the same bits in give the same bits out.
/// </summary>
internal static class SameBits
{
    /// <summary>True when both numbers have the same bits.</summary>
    public static bool Of(double a, double b) => BitConverter.DoubleToInt64Bits(a) == BitConverter.DoubleToInt64Bits(b);

    /// <summary>True when every coordinate has the same bits.</summary>
    public static bool Of(in Vector a, in Vector b) => Of(a.X, b.X) && Of(a.Y, b.Y) && Of(a.Z, b.Z);

    /// <summary>True when every quaternion component has the same bits.</summary>
    public static bool Of(in Rotation a, in Rotation b) => Of(a.W, b.W) && Of(a.X, b.X) && Of(a.Y, b.Y) && Of(a.Z, b.Z);

    /// <summary>True when position and orientation have the same bits.</summary>
    public static bool Of(in Pose a, in Pose b) => Of(a.Position, b.Position) && Of(a.Rotation, b.Rotation);

    /// <summary>True when every joint has the same bits.</summary>
    public static bool Of(in Joints a, in Joints b) =>
        Of(a.J1, b.J1) && Of(a.J2, b.J2) && Of(a.J3, b.J3) && Of(a.J4, b.J4) && Of(a.J5, b.J5) && Of(a.J6, b.J6);
}
