using Machina.Simulation;
using Machina.Simulation.Twin;

namespace Machina.Tests.Simulation.Twin;

/// <summary>
/// A streamed linear motion in program time (the twins' usual case) is one step: the arm plans its way as values and makes the
/// path a part-way motion follows only when the motion is interpolated or paced (it made a closure of the plan and a delegate,
/// about 0.45 KB, for every linear motion).
/// </summary>
public class TwinArmLinearAllocationTests
{
    private static readonly RobotModel Model = RobotModels.Get("KR 6 R900 sixx");
    private static readonly Joints Start = new(0, -90, 90, 0, 45, 0);
    private static readonly Joints Other = new(10, -80, 85, 5, 40, -5);

    [Fact]
    public void MoveLinear_InProgramTime_AllocatesLessThanAPlan_AndEndsAtItsTargets()
    {
        var arm = new TwinArm(Model, Start, new TwinClock(TimeProvider.System, realTime: false)) { MaxTrace = 16 };
        TwinLinearMove there = Move(Other), back = Move(Start);
        for (int i = 0; i < 100; i++)
        {
            arm.MoveLinear(i % 2 == 0 ? there : back, i, "LIN", CancellationToken.None);
        }

        long before = GC.GetAllocatedBytesForCurrentThread();
        for (int i = 0; i < 200; i++)
        {
            arm.MoveLinear(i % 2 == 0 ? there : back, i, "LIN", CancellationToken.None);
        }
        long perMotion = (GC.GetAllocatedBytesForCurrentThread() - before) / 200;

        Assert.True(perMotion < 240, $"{perMotion} bytes per linear motion");
        Assert.Equal(Start, arm.Joints);
        Assert.Equal(Other, arm.Trace[^2].Joints);
    }

    private static TwinLinearMove Move(Joints to) => new(Model.Kinematics.Forward(to), to, 0.25, 2, 0.2, 0, false);
}
