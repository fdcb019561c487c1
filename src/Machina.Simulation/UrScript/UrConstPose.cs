namespace Machina.Simulation.UrScript;

/// <summary>
/// A pose literal whose six elements are number literals, folded when the program is bound: one node with its numbers instead
/// of seven (a compiled program has one per move). Each evaluation still gives a new pose, as a pose can be changed by index.
/// </summary>
internal sealed class UrConstPose(int line, double[] values) : UrExpr(line)
{
    /// <summary>The six numbers.</summary>
    public double[] Values { get; } = values;

    /// <summary><paramref name="expr"/> folded when it is a pose literal of number literals, else <paramref name="expr"/>.</summary>
    public static UrExpr Fold(UrExpr expr)
    {
        if (expr is not UrPoseExpr pose)
        {
            return expr;
        }
        var values = new double[6];
        for (int i = 0; i < 6; i++)
        {
            switch ((pose.Items[i] as UrConst)?.Value)
            {
                case double d:
                    values[i] = d;
                    break;
                case int n:
                    values[i] = n;
                    break;
                default:
                    return expr;
            }
        }
        return new UrConstPose(pose.Line, values);
    }

    /// <inheritdoc/>
    public override object Eval(UrFrame frame) => new UrPose((double[])Values.Clone());
}
