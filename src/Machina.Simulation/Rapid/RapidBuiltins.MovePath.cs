using Machina.Simulation.Twin;

namespace Machina.Simulation.Rapid;

internal static partial class RapidBuiltins
{
    /// <summary>
    /// What the limit zones' check needs of a move's TCP path: the move's values, kept in a struct so that the path's closure
    /// (<see cref="TcpAt"/>) is made only for a task with world zones, not at every move.
    /// </summary>
    /// <param name="Arm">The arm.</param>
    /// <param name="Tool">The tool's frame of the move.</param>
    /// <param name="Arc">The circle of a MoveC, or null.</param>
    /// <param name="Linear">True for a straight TCP path (MoveL): the TCP goes from <paramref name="Start"/> to <paramref name="Goal"/>.</param>
    /// <param name="Start">The TCP where the move starts.</param>
    /// <param name="Goal">The TCP of the target.</param>
    private readonly record struct RapidMovePath(TwinArm Arm, Pose Tool, TwinArc? Arc, bool Linear, Pose Start, Pose Goal)
    {
        /// <summary>The TCP (base frame) at the fraction of the move: on the arc, on the line, or at the joints interpolated from <paramref name="from"/> to <paramref name="to"/>.</summary>
        public Func<double, Vector> TcpAt(Joints from, Joints to)
        {
            TwinArm arm = Arm;
            Pose tool = Tool;
            TwinArc? arc = Arc;
            bool linear = Linear;
            Vector start = Start.Position, goal = Goal.Position;
            return f => arc?.At(f).Position ?? (linear ? start + (goal - start) * f : ToolAt(arm, Between(from, to, f), tool));
        }
    }

    /// <summary>The TCP (base frame) of the arm at <paramref name="joints"/> with <paramref name="tool"/>.</summary>
    private static Vector ToolAt(TwinArm arm, Joints joints, Pose tool) => (arm.Model.Kinematics.Forward(joints) * tool).Position;
}
