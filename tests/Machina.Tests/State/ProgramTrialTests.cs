namespace Machina.Tests.State;

/// <summary>ProgramTrial: a dry run on a copy of a robot's state, the public seam the tool's check, preview and run use.</summary>
public sealed class ProgramTrialTests
{
    [Fact]
    public void Try_WithAModel_FollowsThePose_ListsWhatTheArmCannotDo_AndRefusesWhatCannotBeApplied()
    {
        var trial = new ProgramTrial(RobotModels.Get("IRB 120"));

        TrialStep first = trial.Try(Instructions.Parse("Move(10, 0, 0);")[0]);
        TrialStep home = trial.Try(Instructions.Parse("AxesTo(0, 0, 0, 0, 90, 0);")[0]);
        TrialStep down = trial.Try(Instructions.Parse("Move(0, 0, -100);")[0]);
        TrialStep far = trial.Try(Instructions.Parse("MoveTo(2000, 0, 458);")[0]);

        Assert.False(first.Applied);
        Assert.Equal("the current position of the tool is not known yet; start with MoveTo, TransformTo or AxesTo before relative motions.", first.Refusal);
        Assert.True(home.Applied && home.IsMotion);
        Assert.Empty(home.Issues);
        Assert.True(down.Applied);
        Assert.Null(down.Blocking);
        Assert.True(far.Applied);
        Assert.Equal(KinematicIssueKind.Unreachable, far.Blocking?.Kind);
        Assert.Equal(3, trial.AppliedCount);
        // The pose went on to the unreachable target; the joints of the last reachable one are those before it.
        Assert.Equal(new Vector(2000, 0, 458), trial.Position);
        Assert.True(trial.PreviousAxes is Joints before && new Vector(before.J1, before.J2, before.J3).Length < 90, $"{trial.PreviousAxes}");
    }

    [Fact]
    public void Try_MatchesWhatTheRobotItselfComputes_AndStartTrial_LeavesTheRobotUnchanged()
    {
        var robot = Robot.Create("Arm", "ABB", "IRB 120");
        robot.AxesTo(0, 0, 0, 0, 90, 0);
        robot.SpeedTo(120);
        ProgramTrial trial = robot.StartTrial();

        TrialStep step = trial.Try(Instructions.Parse("Move(0, 50, -100);")[0]);

        Assert.True(step.Applied);
        Assert.True(trial.Position!.Value.IsSimilar(new Vector(302, 50, 458), 1e-6), $"{trial.Position}");
        Assert.Equal(120, trial.State.Speed);   // the robot's settings came along
        Assert.True(robot.GetIssuedState().Position!.Value.IsSimilar(new Vector(302, 0, 558), 1e-6));
        Assert.Equal(2, robot.GetProgramActions().Count);

        robot.Move(0, 50, -100);
        Assert.Equal(robot.GetIssuedState().Position, trial.Position);
        Assert.Equal(robot.GetIssuedState().Axes, trial.Axes);
    }

    [Fact]
    public void StartTrial_OnlineUr_RefusesWhatItsDriverCannotRun_BeforeAnythingIsIssued()
    {
        var robot = Robot.Create("Arm", "UR", "UR5e");
        robot.ControlMode("online");
        robot.AxesTo(0, -90, 90, -90, -90, 0);
        ProgramTrial trial = robot.StartTrial();

        TrialStep axis = trial.Try(Instructions.Parse("ExternalAxisTo(1, 10);")[0]);
        TrialStep output = trial.Try(Instructions.Parse("WriteDigital(12, true);")[0]);

        Assert.False(axis.Applied);
        Assert.EndsWith("cannot be streamed to a UR robot: a UR arm has six joints and no external axes to move.", axis.Refusal, StringComparison.Ordinal);
        Assert.False(output.Applied);
        Assert.Contains("cannot be streamed to a UR robot", output.Refusal, StringComparison.Ordinal);
        Assert.Equal(0, trial.AppliedCount);
        Assert.Single(robot.GetPendingActions());   // only the AxesTo; nothing tried was issued
    }
}
