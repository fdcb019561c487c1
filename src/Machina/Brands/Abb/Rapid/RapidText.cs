using System.Runtime.CompilerServices;
using System.Text;

namespace Machina;

/// <summary>
/// RAPID text pieces: numbers, robtargets, jointtargets, tooldata, string literals, comments and identifiers.
/// All RAPID units live here: millimetres, quaternions (W first), degrees, seconds, m/s².
/// </summary>
internal static class RapidText
{
    /// <summary>RAPID's limit on the length of a string value (TPWrite shows at most this many characters).</summary>
    internal const int MaxStringLength = RapidFacts.MaxStringLength;

    private const int Mm = RapidFacts.MillimetreDecimals;
    private const int Q = RapidFacts.QuaternionDecimals;

    /// <summary>RAPID's limit on the length of an identifier.</summary>
    internal const int MaxIdentifierLength = 32;


    /// <summary>Appends <paramref name="value"/> rounded to <paramref name="decimals"/> (midpoint to even), invariant, −0 as 0.</summary>
    internal static StringBuilder Num(this StringBuilder sb, double value, int decimals) => sb.AppendFixed(value, decimals);

    /// <summary>Appends <c>[x, y, z]</c> in mm with 3 decimals.</summary>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    internal static StringBuilder Position(this StringBuilder sb, Vector p) =>
        sb.Append('[').Num(p.X, Mm).Append(", ").Num(p.Y, Mm).Append(", ").Num(p.Z, Mm).Append(']');

    /// <summary>Appends the quaternion <c>[q1, q2, q3, q4]</c> (W first) with 4 decimals.</summary>
    internal static StringBuilder Quaternion(this StringBuilder sb, Rotation r) =>
        sb.Append('[').Num(r.W, Q).Append(", ").Num(r.X, Q).Append(", ").Num(r.Y, Q).Append(", ").Num(r.Z, Q).Append(']');

    /// <summary>Appends six external-axis values with 3 decimals, <c>9E9</c> for axes without a value; <paramref name="first"/> overrides axis 1.</summary>
    internal static StringBuilder ExternalAxes(this StringBuilder sb, ExternalAxes? axes, double? first = null)
    {
        sb.Append('[');
        for (int i = 1; i <= Machina.ExternalAxes.Count; i++)
        {
            if (i > 1)
            {
                sb.Append(',');
            }
            double? value = i == 1 && first is not null ? first : axes?[i];
            if (value is double v)
            {
                sb.Num(v, Mm);
            }
            else
            {
                sb.Append(RapidFacts.UnusedAxisText);
            }
        }
        return sb.Append(']');
    }

    /// <summary>
    /// Appends a robtarget: position, orientation, configuration (<paramref name="conf"/> when the joints are known from a robot model,
    /// else <c>[0,0,0,0]</c> and the controller chooses), external axes.
    /// </summary>
    internal static StringBuilder RobTarget(this StringBuilder sb, Vector position, Rotation rotation, ExternalAxes? axes, double? armAngle, AbbConfiguration? conf = null) =>
        sb.Append('[').Position(position).Append(", ").Quaternion(rotation).Append(", ").Append(conf is AbbConfiguration c ? c.ToRapid() : "[0,0,0,0]").Append(", ")
          .ExternalAxes(axes, armAngle).Append(']');

    /// <summary>The confdata of the cursor's joints when an ABB model is set and the joints are known, else null.</summary>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    internal static AbbConfiguration? Conf(RobotModel? model, RobotCursor cursor) =>
        model is { Brand: "ABB" } && cursor.Axes is Joints j ? AbbConfiguration.From(model, j) : null;

    /// <summary>Appends a jointtarget: six joint angles in degrees (3 decimals) and the external axes.</summary>
    internal static StringBuilder JointTarget(this StringBuilder sb, Joints j, ExternalAxes? axes) =>
        sb.Append("[[").Num(j.J1, Mm).Append(", ").Num(j.J2, Mm).Append(", ").Num(j.J3, Mm).Append(", ").Num(j.J4, Mm)
          .Append(", ").Num(j.J5, Mm).Append(", ").Num(j.J6, Mm).Append("], ").ExternalAxes(axes).Append(']');

    /// <summary>
    /// tooldata: held by the robot, TCP frame (mm, quaternion), load (kg, centre of gravity in mm, principal axes, no inertia).
    /// RAPID refuses a load of 0 kg, so a weightless tool is declared with 0.001 kg.
    /// </summary>
    internal static string ToolData(Tool tool)
    {
        var sb = new StringBuilder(96);
        Vector t = tool.TcpPosition, c = tool.CenterOfGravity;
        Rotation q = tool.TcpOrientation;
        sb.Append("[TRUE,[[").Num(t.X, Mm).Append(',').Num(t.Y, Mm).Append(',').Num(t.Z, Mm).Append("],[")
          .Num(q.W, Q).Append(',').Num(q.X, Q).Append(',').Num(q.Y, Q).Append(',').Num(q.Z, Q).Append("]],[")
          .Num(Math.Max(tool.Weight, MinToolMass), 3).Append(",[").Num(c.X, Mm).Append(',').Num(c.Y, Mm).Append(',').Num(c.Z, Mm)
          .Append("],[1,0,0,0],0,0,0]]");
        return sb.ToString();
    }

    /// <summary>The smallest tool mass RAPID accepts in a declaration here, kg.</summary>
    internal const double MinToolMass = 0.001;

    /// <summary>speeddata <c>[v,v,v,v]</c>: TCP mm/s, reorientation deg/s, linear and rotating external axes (Machina's "mm/s or deg/s").</summary>
    internal static string SpeedData(double speed)
    {
        string v = NumAppend.Format(speed, 3);
        return $"[{v},{v},{v},{v}]";
    }

    /// <summary>zonedata for a blend radius p (mm): <c>[FALSE,p,1.5p,1.5p,0.1p,1.5p,0.1p]</c>.</summary>
    internal static string ZoneData(double p) =>
        ZoneData(NumAppend.Format(p, 4), NumAppend.Format(1.5 * p, 4), NumAppend.Format(0.1 * p, 4));

    private static string ZoneData(string tcp, string wide, string ori) => $"[FALSE,{tcp},{wide},{wide},{ori},{wide},{ori}]";

    /// <summary>
    /// Splits a user text into RAPID string literals of at most 80 characters each, one per line of the text.
    /// Quotes and backslashes are doubled (RAPID's escapes), other control and non-ASCII characters become '?'.
    /// </summary>
    internal static List<string> StringLiterals(string text, out bool wasSplit, out bool wasChanged)
    {
        var literals = new List<string>();
        wasSplit = false;
        wasChanged = false;
        string[] lines = text.Replace("\r\n", "\n", StringComparison.Ordinal).Split('\n', '\r');
        var sb = new StringBuilder(MaxStringLength * 2 + 2);
        foreach (string line in lines)
        {
            int start = 0;
            do
            {
                int count = Math.Min(MaxStringLength, line.Length - start);
                if (start > 0)
                {
                    wasSplit = true;
                }
                sb.Clear().Append('"');
                for (int i = start; i < start + count; i++)
                {
                    char c = line[i];
                    if (c == '"' || c == '\\')
                    {
                        sb.Append(c).Append(c);
                    }
                    else if (c < ' ' || c > '~')
                    {
                        sb.Append('?');
                        wasChanged = true;
                    }
                    else
                    {
                        sb.Append(c);
                    }
                }
                literals.Add(sb.Append('"').ToString());
                start += count;
            }
            while (start < line.Length);
        }
        return literals;
    }

    /// <summary>A text safe inside a one-line comment: line breaks and control characters become spaces.</summary>
    internal static string CommentText(string text) => ProgramText.CommentText(text);

    /// <summary>The comment lines of actions without code, as <c>!</c> comments.</summary>
    internal static readonly ProgramNotes Notes = new("!", CommentText);
}
