using System.Text;

namespace Machina;

/// <summary>
/// Machina values in KRL units and text: positions in mm, orientations as A, B, C Euler angles in degrees, speeds in m/s,
/// accelerations in m/s², times in seconds. Numbers are invariant, rounded, never in exponent form and never "-0".
/// </summary>
internal static class KrlFormat
{
    /// <summary>mm and degrees: 3 decimals.</summary>
    internal static string Mm(double value) => NumAppend.Format(value, 3);

    /// <summary>m/s, m/s² and seconds: 6 decimals.</summary>
    internal static string Fine(double value) => NumAppend.Format(value, 6);

    /// <summary>The smallest speed (m/s) or acceleration (m/s²) written: a value above 0 that would print as 0 is raised to it.</summary>
    internal const double MinRate = 0.000001;

    /// <summary>True when a speed or acceleration above 0 (mm/s, mm/s²) would print as 0 in m/s or m/s² with 6 decimals.</summary>
    internal static bool RoundsToZero(double perMm) => perMm > 0 && Math.Round(perMm / 1000, 6) < MinRate;

    /// <summary>Speed in mm/s as KRL's <c>$VEL.CP</c> value in m/s (at least <see cref="MinRate"/>).</summary>
    internal static string SpeedMetresPerSecond(double mmPerSecond) => Fine(PerMetre(mmPerSecond));

    /// <summary>Acceleration in mm/s² (above 0) as KRL's <c>$ACC.CP</c> value in m/s² (at least <see cref="MinRate"/>).</summary>
    internal static string AccelerationMetresPerSecond2(double mmPerSecond2) => Fine(PerMetre(mmPerSecond2));

    /// <summary>A speed (mm/s) or acceleration (mm/s²) in m/s or m/s², rounded to 6 decimals and at least <see cref="MinRate"/>.</summary>
    internal static double PerMetre(double perMm) => Math.Max(Math.Round(perMm / 1000, 6), MinRate);

    /// <summary>Milliseconds as KRL's <c>WAIT SEC</c> value in seconds, exact and never in exponent form.</summary>
    internal static string Seconds(long milliseconds) => ProgramText.Seconds(milliseconds);

    /// <summary>
    /// KUKA's A, B, C of an orientation: intrinsic Z-Y′-X″ Euler angles in degrees, A about Z, B about the new Y (in [−90°, 90°]),
    /// C about the new X. Machina's and KUKA's frames agree (tool direction = Z), so no extra turn is applied.
    /// </summary>
    internal static (double A, double B, double C) Abc(Rotation rotation)
    {
        YawPitchRoll ypr = rotation.ToYawPitchRoll();
        return (ypr.Yaw, ypr.Pitch, ypr.Roll);
    }

    /// <summary>An angle in degrees with 3 decimals; −180 is written as 180 (the same angle).</summary>
    internal static string Angle(double degrees) => AppendAngle(new StringBuilder(12), degrees).ToString();

    private static StringBuilder AppendAngle(StringBuilder sb, double degrees) => sb.AppendFixed(Degrees(degrees), 3);

    /// <summary>An angle with −180 (to 3 decimals) turned into 180, the same angle: how KRL programs and the online driver get it.</summary>
    internal static double Degrees(double degrees) => Math.Round(degrees * 1000) == -180_000 ? 180 : degrees;

    /// <summary>The rotation of KUKA's A, B, C (degrees): the inverse of <see cref="Abc"/>.</summary>
    internal static Rotation FromAbc(double a, double b, double c) => Rotation.FromYawPitchRoll(a, b, c);

    private static StringBuilder AppendMm(StringBuilder sb, double value) => sb.AppendFixed(value, 3);

    /// <summary>
    /// Appends <c>X …, Y …, Z …, A …, B …, C …</c>, then <c>, S 'B…', T 'B…'</c> when <paramref name="config"/> is given (joints known
    /// from a robot model), and <c>, E1 …</c> for each external axis that has a value.
    /// </summary>
    internal static void AppendPose(StringBuilder sb, Vector position, Rotation rotation, ExternalAxes? external, KukaConfiguration? config = null)
    {
        AppendPosition(sb, position);
        AppendOrientation(sb, Abc(rotation), external, config);
    }

    /// <summary>The first half of <see cref="AppendPose"/>: <c>X …, Y …, Z …</c>.</summary>
    internal static void AppendPosition(StringBuilder sb, Vector position)
    {
        AppendMm(sb.Append("X "), position.X);
        AppendMm(sb.Append(", Y "), position.Y);
        AppendMm(sb.Append(", Z "), position.Z);
    }

    /// <summary>
    /// The second half of <see cref="AppendPose"/>, with the orientation's <see cref="Abc"/> already known: <c>, A …, B …, C …</c>,
    /// then Status and Turn and the external axes that have a value.
    /// </summary>
    internal static void AppendOrientation(StringBuilder sb, (double A, double B, double C) abc, ExternalAxes? external, KukaConfiguration? config)
    {
        (double a, double b, double c) = abc;
        AppendAngle(sb.Append(", A "), a);
        AppendAngle(sb.Append(", B "), b);
        AppendAngle(sb.Append(", C "), c);
        if (config is KukaConfiguration st)
        {
            sb.Append(", S ").Append(st.StatusText).Append(", T ").Append(st.TurnText);
        }
        AppendExternal(sb, external);
    }

    /// <summary>Appends <c>A1 …, A2 …, …, A6 …</c> (degrees, as given) and <c>, E1 …</c> for each external axis that has a value.</summary>
    internal static void AppendAxes(StringBuilder sb, Joints joints, ExternalAxes? external)
    {
        for (int i = 0; i < Joints.Count; i++)
        {
            sb.Append(i == 0 ? "A" : ", A").Append(AxisDigits[i]).Append(' ');
            AppendMm(sb, joints[i]);
        }
        AppendExternal(sb, external);
    }

    private static readonly char[] AxisDigits = ['1', '2', '3', '4', '5', '6'];

    private static void AppendExternal(StringBuilder sb, ExternalAxes? external)
    {
        if (external is not ExternalAxes ext)
        {
            return;
        }
        for (int i = 1; i <= ExternalAxes.Count; i++)
        {
            if (ext[i] is double v)
            {
                AppendMm(sb.Append(", E").Append(AxisDigits[i - 1]).Append(' '), v);
            }
        }
    }

    /// <summary>True when at least one external axis has a value.</summary>
    internal static bool HasExternal(ExternalAxes? external) => external is ExternalAxes e && !e.IsEmpty;

    /// <summary>A tool as a KRL FRAME: <c>{X …, Y …, Z …, A …, B …, C …}</c>, the tool tip and tip frame relative to the flange.</summary>
    internal static string ToolFrame(Tool tool)
    {
        var sb = new StringBuilder(64);
        sb.Append('{');
        AppendPose(sb, tool.TcpPosition, tool.TcpOrientation, null);
        return sb.Append('}').ToString();
    }
}
