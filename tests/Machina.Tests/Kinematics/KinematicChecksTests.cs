namespace Machina.Tests.Kinematics;

public class KinematicChecksTests
{
    private static readonly RobotModel Irb120 = RobotModels.Get("IRB 120");

    private static List<KinematicIssueKind> Kinds(IReadOnlyList<KinematicIssue> issues) => issues.Select(i => i.Kind).ToList();

    [Fact]
    public void Check_LineShortEnoughForOneSample_ArrivesWithTheTargetsSolutionClosestToTheStart()
    {
        // The path's only sample is the target itself: the solution the check found for the target is the one it arrives with
        // (taken, not solved again), exactly what solving the target from the start gives.
        var start = new Joints(10, 20, 30, 40, 50, 60);
        Pose from = Irb120.Kinematics.Forward(start);
        var target = new Pose(from.Position + new Vector(1, 0, 0), from.Rotation);

        var issues = KinematicChecks.Check(Irb120, start, target, KinematicMotion.Linear, 100, Pose.Identity, out Joints? solution);

        Assert.Empty(issues);
        Assert.NotNull(solution);
        Assert.Equal(Irb120.Kinematics.Closest(target, start), solution);
        Assert.NotEqual(start, solution);
    }

    [Fact]
    public void Check_FarPose_Unreachable()
    {
        var issues = KinematicChecks.Check(Irb120, null, new Pose(2000, 0, 300, Rotation.FlippedAroundY), KinematicMotion.Joint, 100);
        Assert.Equal([KinematicIssueKind.Unreachable], Kinds(issues));
        Assert.Contains("out of reach", issues[0].Reason);
    }

    [Fact]
    public void Check_JointsBeyondLimits_JointLimitNamesTheJoint()
    {
        var issues = KinematicChecks.Check(Irb120, null, new Joints(0, 0, 95, 0, 30, 0), KinematicMotion.Joint, 100);
        Assert.Equal([KinematicIssueKind.JointLimit], Kinds(issues));
        Assert.Contains("joint 3 at 95°, allowed -110° to 70°", issues[0].Reason);
        Assert.Equal((3, 70.0), (issues[0].Joint, issues[0].Limit));
    }

    [Fact]
    public void Check_PoseOnlyReachableBeyondLimits_JointLimit()
    {
        RobotModel narrow = RobotModel.FromOpw("narrow", "ABB", Irb120.Opw!.Value, new Joints(-10, -110, -110, -160, -120, -400), new Joints(10, 110, 70, 160, 120, 400));
        Pose target = Irb120.Kinematics.Forward(new Joints(45, 0, 0, 0, 30, 0));
        var issues = KinematicChecks.Check(narrow, null, target, KinematicMotion.Joint, 100);
        Assert.Equal([KinematicIssueKind.JointLimit], Kinds(issues));
        // Axis 1 needs 45° (limit 10°); the other ways (axis 1 at −135°) are further from allowed.
        Assert.Equal((1, 10.0), (issues[0].Joint, issues[0].Limit));
        Assert.Contains("the nearest needs joint 1 at 45°, 35° past its limit of 10° (allowed -10° to 10°)", issues[0].Reason);
    }

    [Fact]
    public void Check_StraightWrist_WristSingularity()
    {
        Assert.Equal([KinematicIssueKind.WristSingularity], Kinds(KinematicChecks.Check(Irb120, null, new Joints(0, 0, 0, 0, 1, 0), KinematicMotion.Joint, 100)));
    }

    [Fact]
    public void Check_StretchedElbow_ElbowSingularity()
    {
        // Stretched when J3 = atan(70/302) − 90° = −76.95° (J2 = 30° keeps the wrist away from axis 1).
        Assert.Equal([KinematicIssueKind.ElbowSingularity], Kinds(KinematicChecks.Check(Irb120, null, new Joints(0, 30, -76.5, 0, 30, 0), KinematicMotion.Joint, 100)));
    }

    [Fact]
    public void Check_WristCentreOnAxis1_ShoulderSingularity()
    {
        RobotModel m = RobotModels.Get("IRB 1200-7/0.7");
        double j3 = -90 + Math.Atan2(42, 351) * Angles.ToDegrees;
        Assert.Contains(KinematicIssueKind.ShoulderSingularity, Kinds(KinematicChecks.Check(m, null, new Joints(0, 0, j3, 0, 30, 0), KinematicMotion.Joint, 100)));
    }

    [Fact]
    public void Check_ShortLineInsideWorkspace_NoIssue()
    {
        Joints start = new(0, 10, 10, 0, 45, 0);
        Pose from = Irb120.Kinematics.Forward(start);
        var to = new Pose(from.Position + new Vector(0, 50, -30), from.Rotation);
        Assert.Empty(KinematicChecks.Check(Irb120, start, to, KinematicMotion.Linear, 100));
    }

    [Fact]
    public void Check_LineToOtherWristConfiguration_ConfigurationFlip()
    {
        // Same pose, wrist flipped (IRB 1200: axis 4 allows ±270°): a straight line cannot get there.
        RobotModel m = RobotModels.Get("IRB 1200-5/0.9");
        var issues = KinematicChecks.Check(m, new Joints(0, 0, 0, 0, 30, 0), new Joints(0, 0, 0, 180, -30, 180), KinematicMotion.Linear, 100);
        Assert.Contains(KinematicIssueKind.ConfigurationFlip, Kinds(issues));
        Assert.DoesNotContain(KinematicIssueKind.ConfigurationFlip, Kinds(KinematicChecks.Check(m, new Joints(0, 0, 0, 0, 30, 0), new Joints(0, 0, 0, 180, -30, 180), KinematicMotion.Joint, 100)));
    }

    [Fact]
    public void Check_LineThroughStraightWrist_WristSingularityAndFlip()
    {
        var issues = KinematicChecks.Check(Irb120, new Joints(0, 0, 0, 0, 20, 0), new Joints(0, 0, 0, 0, -20, 0), KinematicMotion.Linear, 100);
        Assert.Contains(KinematicIssueKind.WristSingularity, Kinds(issues));
        Assert.Contains(KinematicIssueKind.ConfigurationFlip, Kinds(issues));
    }

    [Fact]
    public void Check_FastLineOnSlowModel_JointSpeed()
    {
        RobotModel slow = RobotModel.FromOpw("slow", "ABB", Irb120.Opw!.Value, Irb120.MinJoints, Irb120.MaxJoints, new Joints(1, 1, 1, 1, 1, 1));
        Joints start = new(0, 10, 10, 0, 45, 0);
        Pose from = slow.Kinematics.Forward(start);
        var to = new Pose(from.Position + new Vector(0, 100, 0), from.Rotation);
        var issues = KinematicChecks.Check(slow, start, to, KinematicMotion.Linear, 500);
        Assert.Equal([KinematicIssueKind.JointSpeed], Kinds(issues));
        Assert.Contains("above its maximum of 1°/s", issues[0].Reason);
        Assert.Empty(KinematicChecks.Check(Irb120, start, to, KinematicMotion.Linear, 500));
    }

    [Fact]
    public void Check_LineLeavingReach_Unreachable()
    {
        Joints start = new(0, 10, 10, 0, 45, 0);
        Pose from = Irb120.Kinematics.Forward(start);
        var to = new Pose(from.Position + new Vector(2000, 0, 0), from.Rotation);
        Assert.Equal([KinematicIssueKind.Unreachable], Kinds(KinematicChecks.Check(Irb120, start, to, KinematicMotion.Linear, 100)));
    }
}
