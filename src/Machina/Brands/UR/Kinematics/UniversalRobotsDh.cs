namespace Machina;

/// <summary>
/// The Denavit–Hartenberg lengths (mm) of a Universal Robots arm, with UR's own signs (a2 and a3 are negative), as published by
/// Universal Robots in "DH Parameters for calculations of kinematics and dynamics". The twists are always 90°, 0, 0, 90°, −90°, 0.
/// </summary>
/// <param name="D1">Base to shoulder height (mm).</param>
/// <param name="A2">Upper-arm length (mm, negative).</param>
/// <param name="A3">Forearm length (mm, negative).</param>
/// <param name="D4">Offset of wrist 1 (mm).</param>
/// <param name="D5">Offset of wrist 2 (mm).</param>
/// <param name="D6">Offset of wrist 3 to the flange (mm).</param>
public readonly record struct UniversalRobotsDh(double D1, double A2, double A3, double D4, double D5, double D6)
{
    internal void Validate()
    {
        foreach (double v in (ReadOnlySpan<double>)[D1, A2, A3, D4, D5, D6])
        {
            Num.Finite(v, "DH parameter");
        }
        if (A2 == 0 || A3 == 0 || D6 == 0)
        {
            throw new ArgumentException($"UR DH parameters need non-zero a2, a3 and d6 (got a2 = {Num.G(A2)}, a3 = {Num.G(A3)}, d6 = {Num.G(D6)}).");
        }
    }
}
