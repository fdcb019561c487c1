using System.Globalization;

namespace Machina;

/// <summary>
/// Text of the messages the RAPID driver and monitor send (spec online §6.2, §6.4), as our driver writes them.
/// Used by the virtual controller; the host reads them back with <see cref="AbbMessageReader"/>.
/// </summary>
internal static class AbbMessageFormat
{
    /// <summary>The version our RAPID driver module declares (protocol 1.4, with the fixes listed in docs/protocol-abb.md; 1.7 reads request 31, an arc's through-point orientation).</summary>
    public static AbbDriverVersion DriverVersion => new(1, 7, 0);

    /// <summary>The first driver version whose handshake ends with <c>$25</c> (its progress).</summary>
    public static AbbDriverVersion FirstWithProgress => new(1, 6, 0);

    /// <summary><c>@id code;</c>, or <c>code;</c> when the request had id 0.</summary>
    public static string Acknowledgement(int id, int code) =>
        id == 0 ? code.ToString(CultureInfo.InvariantCulture) + ";" : "@" + id.ToString(CultureInfo.InvariantCulture) + " " + code.ToString(CultureInfo.InvariantCulture) + ";";

    /// <summary><c>$20 major minor patch;</c></summary>
    public static string Version(AbbDriverVersion version) => $"$20 {version.Major} {version.Minor} {version.Patch};";

    /// <summary><c>$21 x y z qw qx qy qz;</c> with 3 decimals for mm and 4 for the quaternion.</summary>
    public static string Pose(Vector position, Rotation rotation) => "$21 " + PoseValues(position, rotation) + ";";

    /// <summary><c>$22 j1 … j6;</c> in degrees with 3 decimals.</summary>
    public static string Joints(Joints joints) => "$22 " + JointValues(joints) + ";";

    /// <summary><c>$23 e1 … e6;</c> in exponent notation, unset axes as 9E9.</summary>
    public static string ExternalAxes(ExternalAxes axes) => "$23 " + AxisValues(axes) + ";";

    /// <summary><c>$25 lastExecutedId lastReceivedId;</c>: where the driver is in the request stream (0 when nothing yet).</summary>
    public static string Progress(int lastExecutedId, int lastReceivedId) =>
        "$25 " + lastExecutedId.ToString(CultureInfo.InvariantCulture) + " " + lastReceivedId.ToString(CultureInfo.InvariantCulture) + ";";

    /// <summary>The three chunks of a monitor report: <c>$24 pose&gt;</c>, <c>joints&gt;</c>, <c>axes;</c>.</summary>
    public static (string Pose, string Joints, string Axes) MonitorChunks(Vector position, Rotation rotation, Joints joints, ExternalAxes axes) =>
        ("$24 " + PoseValues(position, rotation) + ">", JointValues(joints) + ">", AxisValues(axes) + ";");

    private static string PoseValues(Vector p, Rotation r) =>
        $"{Num.F(p.X, 3)} {Num.F(p.Y, 3)} {Num.F(p.Z, 3)} {Num.F(r.W, 4)} {Num.F(r.X, 4)} {Num.F(r.Y, 4)} {Num.F(r.Z, 4)}";

    private static string JointValues(Joints j) =>
        $"{Num.F(j.J1, 3)} {Num.F(j.J2, 3)} {Num.F(j.J3, 3)} {Num.F(j.J4, 3)} {Num.F(j.J5, 3)} {Num.F(j.J6, 3)}";

    private static string AxisValues(ExternalAxes axes)
    {
        var parts = new string[Machina.ExternalAxes.Count];
        for (int i = 0; i < parts.Length; i++)
        {
            double v = axes[i + 1] ?? AbbRequest.UnusedAxis;
            parts[i] = Num.Clean(Math.Round(v, 3)).ToString("0.000E+00", CultureInfo.InvariantCulture);
        }
        return string.Join(' ', parts);
    }
}
