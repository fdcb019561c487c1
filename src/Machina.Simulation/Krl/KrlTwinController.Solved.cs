using System.Runtime.CompilerServices;

namespace Machina.Simulation.Krl;

/// <summary>
/// What motion keeps from one statement to the next: the poses of $BASE and $TOOL while their components stay the same, and the
/// last target solved. The Machina driver solves each Cartesian target twice, with INVERSE in its check and again in the LIN,
/// from the same axes: the second gets the first's answer. Each is kept whole in one object that is replaced (never changed), so
/// the robot and submit interpreters may read them at once; a key is compared to the bit.
/// </summary>
internal sealed partial class KrlTwinController
{
    private KeptFrame? _keptBase;
    private KeptFrame? _keptTool;
    private KeptSolution? _keptSolution;

    /// <summary>A frame's six components (X, Y, Z, A, B, C), its pose and the pose's inverse (made once: a motion used it each time).</summary>
    private sealed class KeptFrame(double[] components, Pose pose)
    {
        public double[] Components { get; } = components;

        public Pose Pose { get; } = pose;

        public Pose Inverse { get; } = pose.Inverse();
    }

    /// <summary>
    /// A target solved: the frames and the target's six components, the axes it was solved from, and the answer; with the target's
    /// pose in $BASE (<see cref="To"/>) and in the robot's base frame (<see cref="Goal"/>), which the motion to it uses again.
    /// </summary>
    private sealed class KeptSolution(IKinematics kinematics, KeptFrame baseFrame, KeptFrame tool, ReadOnlySpan<double> target, Joints near, Joints? solution,
        string why, Pose to, Pose goal)
    {
        private readonly TargetComponents _target = TargetComponents.Of(target);

        public IKinematics Kinematics { get; } = kinematics;

        public KeptFrame Base { get; } = baseFrame;

        public KeptFrame Tool { get; } = tool;

        /// <summary>True when <paramref name="target"/>'s six components are the kept target's, to the bit.</summary>
        public bool IsFor(ReadOnlySpan<double> target) => Same(_target, target);

        public Joints Near { get; } = near;

        public Joints? Solution { get; } = solution;

        public string Why { get; } = why;

        public Pose To { get; } = to;

        public Pose Goal { get; } = goal;
    }

    /// <summary>A solved target's six components, held in its <see cref="KeptSolution"/> (no array of its own per solve).</summary>
    [InlineArray(6)]
    private struct TargetComponents
    {
        private double _first;

        public static TargetComponents Of(ReadOnlySpan<double> components)
        {
            TargetComponents kept = default;
            components.CopyTo(kept);
            return kept;
        }
    }

    /// <summary>$BASE as a pose (taken again while its components are the same).</summary>
    private Pose BaseFrame() => KeptBase().Pose;

    private KeptFrame KeptBase() => Kept(Motion.Base, ref _keptBase);

    private KeptFrame KeptTool() => Kept(Motion.Tool, ref _keptTool);

    /// <summary>The frame kept in <paramref name="kept"/> while the one in <paramref name="cell"/> has its components, else the frame now (kept).</summary>
    private static KeptFrame Kept(KrlCell cell, ref KeptFrame? kept)
    {
        var frame = (KrlStructValue)cell.Value;
        Span<double> components = stackalloc double[6];
        PoseComponents(frame, components);
        if (kept is { } now && Same(now.Components, components))
        {
            return now;
        }
        return kept = new KeptFrame(components.ToArray(), PoseOf(components));
    }

    /// <summary>X, Y, Z, A, B and C of a FRAME, POS or E6POS value (0 for a component its type lacks).</summary>
    private static void PoseComponents(KrlStructValue frame, Span<double> components)
    {
        int[] indexes = frame.Type.PoseIndexes;
        for (int i = 0; i < 6; i++)
        {
            components[i] = indexes[i] >= 0 ? frame.Real(indexes[i]) : 0;
        }
    }

    private static Pose PoseOf(ReadOnlySpan<double> c) => new(c[0], c[1], c[2], Rotation.FromYawPitchRoll(c[3], c[4], c[5]));

    private static Pose PoseOf(KrlStructValue frame)
    {
        Span<double> components = stackalloc double[6];
        PoseComponents(frame, components);
        return PoseOf(components);
    }

    /// <summary>The answer kept for this target, frames and start, or null.</summary>
    private KeptSolution? KeptFor(IKinematics kinematics, KeptFrame baseFrame, KeptFrame tool, ReadOnlySpan<double> target, Joints near) =>
        _keptSolution is { } kept && ReferenceEquals(kept.Kinematics, kinematics) && ReferenceEquals(kept.Base, baseFrame) && ReferenceEquals(kept.Tool, tool) && kept.IsFor(target)
            && Same(kept.Near, near) ? kept : null;

    private static bool Same(ReadOnlySpan<double> a, ReadOnlySpan<double> b)
    {
        for (int i = 0; i < a.Length; i++)
        {
            if (BitConverter.DoubleToInt64Bits(a[i]) != BitConverter.DoubleToInt64Bits(b[i]))
            {
                return false;
            }
        }
        return true;
    }

    private static bool Same(Joints a, Joints b)
    {
        for (int i = 0; i < Joints.Count; i++)
        {
            if (BitConverter.DoubleToInt64Bits(a[i]) != BitConverter.DoubleToInt64Bits(b[i]))
            {
                return false;
            }
        }
        return true;
    }
}
