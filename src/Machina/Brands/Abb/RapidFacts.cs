namespace Machina;

/// <summary>
/// Facts of the RAPID language that the offline writer (Brands/Abb/Rapid) and the online link (Brands/Abb/Online) share, so
/// that each is written once: string length, the unused-axis marker, and the decimals Machina gives each unit.
/// </summary>
internal static class RapidFacts
{
    /// <summary>Longest RAPID string value (TPWrite shows at most this many characters; the driver reads 80 per statement).</summary>
    internal const int MaxStringLength = 80;

    /// <summary>The value RAPID uses for an external axis that is not in use.</summary>
    internal const double UnusedAxis = 9e9;

    /// <summary><see cref="UnusedAxis"/> as RAPID text.</summary>
    internal const string UnusedAxisText = "9E9";

    /// <summary>Decimals of millimetres and degrees (positions, joints, external axes).</summary>
    internal const int MillimetreDecimals = 3;

    /// <summary>Decimals of quaternion components.</summary>
    internal const int QuaternionDecimals = 4;
}
