using Machina.Simulation.Twin;

namespace Machina.Tests.Simulation.Twin;

/// <summary>
/// The arm looks at the joint limits of joints it already found within them only once (issue 45): a motion's target is checked
/// where the language asks and again where the arm starts the motion. Joints beyond a limit still raise every time, with the
/// joint and its limits, and joints that differ in any bit are looked at again.
/// </summary>
public class TwinArmLimitCheckTests
{
    private static readonly RobotModel Model = TwinArmForwardTests.Model;
    private static readonly Joints Other = TwinArmForwardTests.Other;

    private static TwinArm Arm() => TwinArmForwardTests.Arm();

    [Fact]
    public void SameJointsTwice_AreLookedAtOnce()
    {
        TwinArm arm = Arm();

        arm.RequireWithinLimits(Other);
        arm.RequireWithinLimits(Other);

        Assert.Equal(1, arm.LimitChecks);
    }

    [Fact]
    public void JointsBeyondALimit_RaiseEveryTime_AndOtherJointsAreLookedAtAgain()
    {
        TwinArm arm = Arm();
        var beyond = new Joints(10, -80, 85, 5, 40, Model.MaxJoints.J6 + 1);
        var nearby = new Joints(10, -80, 85, 5, 40, BitConverter.Int64BitsToDouble(BitConverter.DoubleToInt64Bits(-5) + 1));

        arm.RequireWithinLimits(Other);
        TwinMotionException first = Assert.Throws<TwinMotionException>(() => arm.RequireWithinLimits(beyond));
        TwinMotionException second = Assert.Throws<TwinMotionException>(() => arm.RequireWithinLimits(beyond));
        arm.RequireWithinLimits(nearby);
        arm.RequireWithinLimits(Other);

        Assert.StartsWith("joint 6 target ", first.Message, StringComparison.Ordinal);
        Assert.Equal(first.Message, second.Message);
        Assert.Equal(5, arm.LimitChecks);
    }

    [Fact]
    public void LinearMotion_InProgramTime_LooksAtItsTargetsLimitsOnce_AndEndsThere()
    {
        TwinArm arm = Arm();
        Pose target = Model.Kinematics.Forward(Other);

        arm.MoveLinear(new TwinLinearMove(target, Other, 0.25, 2, 0.2, 0, false), 4, "LIN", CancellationToken.None);

        Assert.Equal(1, arm.LimitChecks);
        Assert.Equal(Other, arm.Joints);
        TwinTraceEntry traced = Assert.Single(arm.Trace);
        Assert.True(SameBits.Of(target, traced.Tcp));
    }
}
