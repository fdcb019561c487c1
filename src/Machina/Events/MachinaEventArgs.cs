using System.Text;

namespace Machina;

/// <summary>Base of Machina's event payloads: a consistent snapshot of the robot's state, with a one-line JSON form for bridges and web views.</summary>
public abstract class MachinaEventArgs : EventArgs
{
    private protected MachinaEventArgs(RobotState state) => State = state ?? throw new ArgumentNullException(nameof(state));

    /// <summary>The robot's state when the event happened.</summary>
    public RobotState State { get; }

    /// <summary>Tool tip position (mm), or null when unknown.</summary>
    public Vector? Position => State.Position;

    /// <summary>Tool orientation, or null when unknown.</summary>
    public Rotation? Rotation => State.Rotation;

    /// <summary>Joint angles (degrees), or null when unknown.</summary>
    public Joints? Axes => State.Axes;

    /// <summary>External axes of Cartesian targets (or, when those were never set, of joint targets), or null.</summary>
    public ExternalAxes? ExternalAxes => State.ExternalAxesCartesian ?? State.ExternalAxesJoints;

    /// <summary>The payload as one line of JSON, in the shape the original Machina Bridge sent.</summary>
    public abstract string ToJsonString();

    /// <summary>Same as <see cref="ToJsonString"/> (the original's name).</summary>
    public string ToJSONString() => ToJsonString();

    /// <summary>Same as <see cref="ToJsonString"/>.</summary>
    public override string ToString() => ToJsonString();

    /// <summary>Appends <c>"pos":…,"ori":…,"quat":…,"axes":…,"extax":…,"conf":null</c>.</summary>
    private protected void AppendPose(StringBuilder sb)
    {
        sb.Append("\"pos\":");
        if (Position is Vector p) { sb.Append('[').Append(Num.F(p.X, 3)).Append(',').Append(Num.F(p.Y, 3)).Append(',').Append(Num.F(p.Z, 3)).Append(']'); }
        else { sb.Append("null"); }
        sb.Append(",\"ori\":");
        if (Rotation is Rotation r)
        {
            Vector x = r.XAxis, y = r.YAxis;
            sb.Append('[').AppendJoin(',', Num.F(x.X, 3), Num.F(x.Y, 3), Num.F(x.Z, 3), Num.F(y.X, 3), Num.F(y.Y, 3), Num.F(y.Z, 3)).Append(']');
            sb.Append(",\"quat\":[").AppendJoin(',', Num.F(r.W, 4), Num.F(r.X, 4), Num.F(r.Y, 4), Num.F(r.Z, 4)).Append(']');
        }
        else
        {
            sb.Append("null,\"quat\":null");
        }
        sb.Append(",\"axes\":");
        if (Axes is Joints j)
        {
            sb.Append('[').AppendJoin(',', Num.F(j.J1, 3), Num.F(j.J2, 3), Num.F(j.J3, 3), Num.F(j.J4, 3), Num.F(j.J5, 3), Num.F(j.J6, 3)).Append(']');
        }
        else { sb.Append("null"); }
        sb.Append(",\"extax\":");
        if (ExternalAxes is ExternalAxes e)
        {
            sb.Append('[');
            for (int i = 1; i <= Machina.ExternalAxes.Count; i++)
            {
                if (i > 1) { sb.Append(','); }
                sb.Append(e[i] is double v ? Num.F(v, 3) : "null");
            }
            sb.Append(']');
        }
        else { sb.Append("null"); }
        sb.Append(",\"conf\":null");
    }

    /// <summary>Appends a JSON string literal (the instruction quoting escapes exactly what JSON requires).</summary>
    private protected static void AppendJsonString(StringBuilder sb, string text) => sb.Append(InstructionText.Quote(text));

    /// <summary>Appends <c>"event":"name","last":"instruction","id":n</c>.</summary>
    private protected static void AppendHead(StringBuilder sb, string eventName, RobotAction action)
    {
        sb.Append("{\"event\":\"").Append(eventName).Append("\",\"last\":");
        AppendJsonString(sb, action.ToInstruction());
        sb.Append(",\"id\":").Append(Num.I(action.Id));
    }
}
