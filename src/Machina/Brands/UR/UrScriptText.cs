using System.Text;

namespace Machina;

/// <summary>
/// URScript text pieces. All UR unit conversions live here: positions in metres, orientations as rotation vectors in
/// radians, joint angles in radians, linear speed/acceleration in m/s and m/s², joint speed/acceleration in rad/s and rad/s²,
/// blend radius in metres; 6 decimals.
/// </summary>
internal static class UrScriptText
{
    internal const double Mm = 0.001;
    internal const double Rad = Math.PI / 180;

    private static readonly HashSet<string> Reserved = new(StringComparer.Ordinal)
    {
        "def", "end", "if", "elif", "else", "while", "for", "return", "thread", "run", "kill", "join", "global", "local",
        "and", "or", "not", "xor", "True", "False", "halt", "break", "continue", "pass", "sec", "enter_critical", "exit_critical",
        "movej", "movel", "movep", "movec", "sleep", "popup", "textmsg", "set_tcp", "set_payload", "set_standard_digital_out",
        "set_tool_digital_out", "set_standard_analog_out",
    };

    /// <summary>Appends <paramref name="value"/> rounded to 6 decimals (midpoint to even), invariant, −0 as 0.</summary>
    internal static StringBuilder Num6(this StringBuilder sb, double value) => sb.AppendFixed(value, 6);

    /// <summary>Appends a pose <c>p[x,y,z,rx,ry,rz]</c>: millimetres to metres, rotation to a rotation vector in radians.</summary>
    internal static StringBuilder Pose(this StringBuilder sb, Vector position, Rotation rotation) => sb.PosePosition(position).PoseOrientation(rotation);

    /// <summary>Appends the first half of a pose, <c>p[x,y,z</c>: millimetres to metres.</summary>
    internal static StringBuilder PosePosition(this StringBuilder sb, Vector position) =>
        sb.Append("p[").Num6(position.X * Mm).Append(',').Num6(position.Y * Mm).Append(',').Num6(position.Z * Mm);

    /// <summary>Appends the second half of a pose, <c>,rx,ry,rz]</c>: the rotation as a rotation vector in radians.</summary>
    internal static StringBuilder PoseOrientation(this StringBuilder sb, Rotation rotation)
    {
        RotationVector rv = rotation.ToRotationVector();
        return sb.Append(',').Num6(rv.X * Rad).Append(',').Num6(rv.Y * Rad).Append(',').Num6(rv.Z * Rad).Append(']');
    }

    /// <summary>Appends a joint list <c>[j1,…,j6]</c> in radians.</summary>
    internal static StringBuilder JointList(this StringBuilder sb, Joints j) =>
        sb.Append('[').Num6(j.J1 * Rad).Append(',').Num6(j.J2 * Rad).Append(',').Num6(j.J3 * Rad).Append(',')
          .Num6(j.J4 * Rad).Append(',').Num6(j.J5 * Rad).Append(',').Num6(j.J6 * Rad).Append(']');

    /// <summary>The smallest speed or acceleration written (6 decimals): a value that would print as 0 is raised to it.</summary>
    internal const double MinRate = 0.000001;

    /// <summary>True when a linear speed or acceleration (mm/s or mm/s²) above 0 would print as 0 in m/s or m/s².</summary>
    internal static bool RoundsToZero(double perMm) => perMm > 0 && Math.Round(perMm * Mm, 6) < MinRate;

    /// <summary>
    /// Appends <c>, a=…, v=…, r=…</c>: linear motions in m/s² and m/s, joint motions in rad/s² and rad/s; blend radius in m.
    /// An acceleration of 0 or Machina's built-in default (30 mm/s², which the original wrote as a crawling 0.03 m/s², spec
    /// bug 34) leaves <c>a</c> out, so the controller uses its own (never <c>a=0</c>); a speed or acceleration above 0 is
    /// written as at least <see cref="MinRate"/>, never as 0.
    /// </summary>
    internal static StringBuilder MotionParameters(this StringBuilder sb, double acceleration, double speed, double precision, bool joint)
    {
        double factor = joint ? Rad : Mm;
        if (!Settings.MeansControllerAcceleration(acceleration))
        {
            sb.Append(", a=").Num6(Math.Max(Math.Round(acceleration * factor, 6), MinRate));
        }
        return sb.Append(", v=").Num6(Math.Max(Math.Round(speed * factor, 6), MinRate)).Append(", r=").Num6(precision * Mm).Append(')');
    }

    /// <summary>Appends <c>set_tcp(p[…])</c> for a tool (or the bare flange when null).</summary>
    internal static string SetTcp(Tool? tool)
    {
        var sb = new StringBuilder(64).Append("  set_tcp(");
        return (tool is null ? sb.Append("p[0,0,0,0,0,0]") : sb.Pose(tool.TcpPosition, tool.TcpOrientation)).Append(')').ToString();
    }

    /// <summary><c>set_payload(kg, [cx,cy,cz])</c> with the centre of gravity in metres (0 kg when no tool).</summary>
    internal static string SetPayload(Tool? tool)
    {
        var sb = new StringBuilder(64).Append("  set_payload(");
        if (tool is null)
        {
            return sb.Append("0, [0,0,0])").ToString();
        }
        Vector c = tool.CenterOfGravity;
        return sb.Num6(tool.Weight).Append(", [").Num6(c.X * Mm).Append(',').Num6(c.Y * Mm).Append(',').Num6(c.Z * Mm).Append("])").ToString();
    }

    /// <summary>
    /// A double-quoted URScript string that cannot end early or break the line: <c>"</c> becomes <c>'</c>, <c>\</c> becomes
    /// <c>/</c>, line breaks and control characters become spaces, non-ASCII characters become '?'.
    /// </summary>
    internal static string StringLiteral(string text, out bool changed)
    {
        changed = false;
        var sb = new StringBuilder(text.Length + 2).Append('"');
        foreach (char c in text)
        {
            char o = c switch
            {
                '"' => '\'',
                '\\' => '/',
                < ' ' => ' ',
                > '~' => '?',
                _ => c,
            };
            changed |= o != c;
            sb.Append(o);
        }
        return sb.Append('"').ToString();
    }

    /// <summary>A text safe inside a <c>#</c> comment: line breaks and control characters become spaces.</summary>
    internal static string CommentText(string text) => ProgramText.CommentText(text);

    /// <summary>The comment lines of actions without code, as <c>#</c> comments.</summary>
    internal static readonly ProgramNotes Notes = new("#", CommentText);

    /// <summary>The program name as a URScript function name: ASCII letters, digits and '_', a letter first, not a keyword or a function this program calls.</summary>
    internal static string FunctionName(string programName)
    {
        var sb = new StringBuilder(programName.Length + 8);
        foreach (char c in programName)
        {
            sb.Append(char.IsAsciiLetterOrDigit(c) || c == '_' ? c : '_');
        }
        if (sb.Length == 0 || !char.IsAsciiLetter(sb[0]))
        {
            sb.Insert(0, 'P');
        }
        string name = sb.ToString();
        bool looksLikeTarget = name.StartsWith("target", StringComparison.Ordinal);
        return Reserved.Contains(name) || looksLikeTarget ? name + "_program" : name;
    }
}
