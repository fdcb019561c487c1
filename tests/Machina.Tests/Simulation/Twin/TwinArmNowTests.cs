using Machina.Simulation;
using Machina.Simulation.Twin;

namespace Machina.Tests.Simulation.Twin;

/// <summary>
/// <see cref="TwinArm.Now"/> reads the joints and the tool centre point in one look at the arm's gate (issue 45): the same values
/// <see cref="TwinArm.Joints"/> and <see cref="TwinArm.Tcp"/> give, bit for bit, with the flange pose kept as before.
/// </summary>
public class TwinArmNowTests
{
    [Fact]
    public void Now_IsTheJointsAndTheTcp_BitForBit_SolvingOnce()
    {
        TwinArm arm = TwinArmForwardTests.Arm();
        arm.ToolCenter = new Pose(new Vector(0, 0, 120), Rotation.Identity);

        (Joints joints, Pose tcp) = arm.Now;
        Pose again = arm.Tcp;

        Assert.Equal(TwinArmForwardTests.Start, joints);
        Pose expected = TwinArmForwardTests.Model.Kinematics.Forward(TwinArmForwardTests.Start) * arm.ToolCenter;
        Assert.True(SameBits.Of(expected, tcp));
        Assert.True(SameBits.Of(expected, again));
        Assert.Equal(1, arm.ForwardSolves);
    }

    [Fact]
    public void AfterAMotion_NowAndTheRecordedStep_AreAtItsTarget()
    {
        TwinArm arm = TwinArmForwardTests.Arm();
        Assert.True(arm.MoveTo(TwinArmForwardTests.Other, 0.5, 7, "PTP", CancellationToken.None));

        arm.Record(8, TwinTraceKind.Output, "$OUT[1] = TRUE");
        (Joints joints, Pose tcp) = arm.Now;

        Assert.Equal(TwinArmForwardTests.Other, joints);
        Assert.Collection(arm.Trace,
            motion => Assert.Equal((7, TwinTraceKind.Motion, TwinArmForwardTests.Other, 0.5), (motion.Line, motion.Kind, motion.Joints, motion.Seconds)),
            output =>
            {
                Assert.Equal((8, TwinTraceKind.Output, TwinArmForwardTests.Other), (output.Line, output.Kind, output.Joints));
                Assert.True(SameBits.Of(tcp, output.Tcp));
            });
        Assert.True(SameBits.Of(TwinArmForwardTests.Model.Kinematics.Forward(TwinArmForwardTests.Other), tcp));
        Assert.Equal(1, arm.ForwardSolves);
    }
}
