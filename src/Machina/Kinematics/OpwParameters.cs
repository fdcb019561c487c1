namespace Machina;

/// <summary>
/// The seven lengths (mm) that describe an "ortho-parallel arm with spherical wrist" (OPW), the layout of almost every
/// ABB and KUKA six-axis arm. Names and signs follow the OPW convention of Brandstötter, Angerer and Hofbaur (2014).
/// </summary>
/// <param name="A1">Forward offset of axis 2 from axis 1 (mm).</param>
/// <param name="A2">Offset between axis 3 and the forearm axis (mm); negative when the forearm runs above axis 3, as on most robots.</param>
/// <param name="B">Sideways offset of the arm plane from axis 1 (mm); 0 on the catalogued robots.</param>
/// <param name="C1">Height of axis 2 above the base (mm).</param>
/// <param name="C2">Lower-arm length, axis 2 to axis 3 (mm).</param>
/// <param name="C3">Forearm length, axis 3 to the wrist centre (mm).</param>
/// <param name="C4">Wrist centre to flange (mm).</param>
public readonly record struct OpwParameters(double A1, double A2, double B, double C1, double C2, double C3, double C4)
{
    internal void Validate()
    {
        foreach (double v in (ReadOnlySpan<double>)[A1, A2, B, C1, C2, C3, C4])
        {
            Num.Finite(v, "OPW parameter");
        }
        if (C2 <= 0 || C3 <= 0 || C4 < 0)
        {
            throw new ArgumentException($"OPW parameters need a positive lower arm (c2 = {Num.G(C2)}), a positive forearm (c3 = {Num.G(C3)}) and a wrist length c4 ≥ 0 (c4 = {Num.G(C4)}).");
        }
    }
}
