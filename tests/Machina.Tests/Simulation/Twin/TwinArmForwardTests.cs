using Machina.Simulation;
using Machina.Simulation.Twin;

namespace Machina.Tests.Simulation.Twin;

/// <summary>
/// The arm keeps the flange pose of the last joints it solved (issue 45): a motion reads the pose of the joints it starts from
/// several times, and the next motion starts where the last one's trace solved. The kept pose must be the one the kinematics
/// gives, bit for bit, and a motion in program time that nothing wakes is one step, solving nothing at its ends.
/// </summary>
public class TwinArmForwardTests
{
    /// <summary>The arm's model in these tests.</summary>
    internal static readonly RobotModel Model = RobotModels.Get("KR 6 R900 sixx");

    /// <summary>Where the arm starts.</summary>
    internal static readonly Joints Start = new(0, -90, 90, 0, 45, 0);

    /// <summary>Other joints within the limits.</summary>
    internal static readonly Joints Other = new(10, -80, 85, 5, 40, -5);

    /// <summary>An arm at <see cref="Start"/> whose motions take program time.</summary>
    internal static TwinArm Arm() => new(Model, Start, new TwinClock(TimeProvider.System, realTime: false));

    [Fact]
    public void Tcp_ReadTwice_SolvesOnce_AndIsTheKinematicsPose_BitForBit()
    {
        TwinArm arm = Arm();
        arm.ToolCenter = new Pose(new Vector(0, 0, 120), Rotation.Identity);

        Pose first = arm.Tcp, second = arm.Tcp;

        Assert.Equal(1, arm.ForwardSolves);
        Pose expected = Model.Kinematics.Forward(Start) * arm.ToolCenter;
        Assert.True(SameBits.Of(expected, first));
        Assert.True(SameBits.Of(expected, second));
    }

    [Fact]
    public void ToolChange_IsSeenAtOnce_TheKeptPoseIsTheFlanges()
    {
        TwinArm arm = Arm();
        Pose before = arm.Tcp;
        arm.ToolCenter = new Pose(new Vector(0, 0, 200), Rotation.Identity);

        Pose after = arm.Tcp;

        Assert.Equal(1, arm.ForwardSolves);
        Assert.Equal(200, Vector.Distance(before.Position, after.Position), 9);
        Assert.True(SameBits.Of(Model.Kinematics.Forward(Start) * arm.ToolCenter, after));
    }

    [Fact]
    public void Motion_ThenTcp_SolvesTheTargetOnce_ForTheTraceAndTheRead()
    {
        TwinArm arm = Arm();

        Assert.True(arm.MoveTo(Other, 0.5, 7, "LIN", CancellationToken.None));
        Pose now = arm.Tcp;

        Assert.Equal(1, arm.ForwardSolves);
        TwinTraceEntry traced = Assert.Single(arm.Trace);
        Assert.True(SameBits.Of(Model.Kinematics.Forward(Other), traced.Tcp));
        Assert.True(SameBits.Of(traced.Tcp, now));
        Assert.Equal(Other, arm.Joints);
    }

    [Fact]
    public void MotionInProgramTime_NothingWakesIt_IsOneStep_WithNoPosesSolvedAtItsEnds()
    {
        TwinArm arm = Arm();
        int wakesAsked = 0;
        arm.NextWake = () =>
        {
            wakesAsked++;
            return -1; // no timer runs
        };

        Assert.True(arm.MoveTo(Other, 0.5, 3, "LIN", CancellationToken.None, trace: false, linear: true));

        // A motion in program time would have solved the tool's pose at its start and its end to keep it on the line.
        Assert.Equal(0, arm.ForwardSolves);
        Assert.Equal(1, wakesAsked);
        Assert.Equal(Other, arm.Joints);
        Assert.Equal(0.5, arm.Clock.Seconds, 9);
    }

    [Fact]
    public void MotionInProgramTime_AWakeWithinIt_IsServedPartWay()
    {
        TwinArm arm = Arm();
        double wakeAt = 0.2;
        var seenAtWake = new List<(double Seconds, Joints Joints)>();
        arm.NextWake = () => wakeAt < 0 ? -1 : wakeAt - arm.Clock.Seconds;
        arm.Serve = () =>
        {
            seenAtWake.Add((arm.Clock.Seconds, arm.Joints));
            wakeAt = -1; // the timer's interrupt ran: it does not run again
        };

        Assert.True(arm.MoveTo(Other, 0.5, 3, "PTP", CancellationToken.None));

        (double seconds, Joints joints) = Assert.Single(seenAtWake);
        Assert.Equal(0.2, seconds, 9);
        Assert.Equal(Start.J1 + (Other.J1 - Start.J1) * 0.4, joints.J1, 9); // part-way: 0.2 s of 0.5 s, straight in joint space
        Assert.Equal(Other, arm.Joints);
        Assert.Equal(0.5, arm.Clock.Seconds, 9);
    }

    /// <summary>
    /// A linear motion in program time is one step: the arm plans its way as values and makes the path a part-way motion follows
    /// only when the motion is interpolated or paced (it made a closure of the plan and a delegate, about 0.45 KB, each time).
    /// </summary>
    [Fact]
    public void MoveLinear_InProgramTime_AllocatesLessThanAPlan_AndEndsAtItsTargets()
    {
        TwinArm arm = new(Model, Start, new TwinClock(TimeProvider.System, realTime: false)) { MaxTrace = 16 };
        TwinLinearMove there = Linear(Other), back = Linear(Start);
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

    private static TwinLinearMove Linear(Joints to) => new(Model.Kinematics.Forward(to), to, 0.25, 2, 0.2, 0, false);
}

/// <summary>How many forward kinematics the KUKA twin's arm runs per streamed 1 mm LIN of our driver (issue 45).</summary>
public class TwinArmStreamedForwardTests
{
    [Fact]
    public async Task KukaTwin_StreamedLines_SolveTheForwardKinematicsAtMostTwicePerMotion()
    {
        await using VirtualKukaController controller = await Machina.Tests.Online.KukaTestSupport.StartKukaAsync();
        var bot = Robot.Create("Forward", "KUKA");
        bot.ControlMode("online");
        await bot.ConnectAsync("127.0.0.1", controller.Port).WaitAsync(TimeSpan.FromMinutes(1));
        bot.SpeedTo(200);
        bot.Move(1, 0, 0); // the first motion (the driver's BCO run) and the connection's reads are counted before
        await bot.WaitForCompletionAsync().WaitAsync(TimeSpan.FromMinutes(1));
        TwinArm arm = controller.Twin!.Arm;
        int before = arm.ForwardSolves;
        int tracedBefore = arm.Trace.Count(t => t.Kind == TwinTraceKind.Motion);
        const int Moves = 40;

        for (int i = 0; i < Moves; i++)
        {
            bot.Move((i & 1) == 0 ? -1 : 1, 0, 0);
        }
        await bot.WaitForCompletionAsync().WaitAsync(TimeSpan.FromMinutes(1));

        // Each LIN read the TCP where the arm stands ($POS_ACT), its start twice more, the motion's start and end, and its trace's
        // end: six solves of two joints. The last joints solved are kept: the start was solved as the last motion's end.
        int solves = arm.ForwardSolves - before;
        Assert.InRange(solves, Moves / 2, 2 * Moves);
        Assert.Equal(Moves, arm.Trace.Count(t => t.Kind == TwinTraceKind.Motion) - tracedBefore);
        await bot.DisconnectAsync();
    }
}
