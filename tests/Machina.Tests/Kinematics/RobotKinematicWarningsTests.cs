namespace Machina.Tests.Kinematics;

public class RobotKinematicWarningsTests
{
    private static readonly RobotModel Irb120 = RobotModels.Get("IRB 120");

    private static List<KinematicIssueKind?> Kinds(IEnumerable<ProgramWarning> warnings) => warnings.Select(w => w.Kind).ToList();

    /// <summary>The robot's one warning, checked to be of <paramref name="kind"/> and raised by action <paramref name="actionId"/>.</summary>
    private static ProgramWarning OnlyWarning(Robot bot, KinematicIssueKind kind, int actionId)
    {
        ProgramWarning w = Assert.Single(bot.GetWarnings());
        Assert.Equal(kind, w.Kind);
        Assert.Equal(actionId, w.ActionId);
        return w;
    }

    /// <summary>An IRB 120 at axis 5 = 45° and axis 6 = <paramref name="j6"/>° turning its tool <paramref name="degrees"/>° about its Z, in a joint move.</summary>
    private static Robot TurnToolInAJointMove(double j6, double degrees)
    {
        Robot bot = Robot.Create("Bot", "ABB", "IRB 120");
        bot.AxesTo(0, 0, 0, 0, 45, j6);
        bot.MotionMode("joint");
        bot.Coordinates("local");
        bot.Rotate(0, 0, 1, degrees);
        return bot;
    }

    [Fact]
    public void AxesTo_BeyondLimit_JointLimitWarningWithActionId()
    {
        Robot bot = Robot.Create("Bot", "ABB", "IRB 120");
        bot.AxesTo(0, 0, 95, 0, 30, 0);
        ProgramWarning w = OnlyWarning(bot, KinematicIssueKind.JointLimit, 1);
        Assert.Equal("#1 AxesTo(0,0,95,0,30,0); JointLimit: the target joints [0, 0, 95, 0, 30, 0] are beyond the limits (joint 3 at 95°, allowed -110° to 70°).", w.ToString());
    }

    [Theory]
    [InlineData("IRB 120", 0, 0, 0, 0, 1, 0, KinematicIssueKind.WristSingularity)]
    [InlineData("IRB 120", 0, 30, -76.5, 0, 30, 0, KinematicIssueKind.ElbowSingularity)]
    [InlineData("IRB 1200-7/0.7", 0, 0, -83.17, 0, 30, 0, KinematicIssueKind.ShoulderSingularity)]
    public void AxesTo_NearSingularity_Warns(string model, double j1, double j2, double j3, double j4, double j5, double j6, KinematicIssueKind kind)
    {
        Robot bot = Robot.Create("Bot", "ABB", model);
        bot.AxesTo(j1, j2, j3, j4, j5, j6);
        Assert.Contains(kind, Kinds(bot.GetWarnings()));
    }

    [Fact]
    public void LinearMoveThroughStraightWrist_WarnsFlipAndWrist()
    {
        Robot bot = Robot.Create("Bot", "ABB", "IRB 120");
        bot.AxesTo(0, 0, 0, 0, 20, 0);
        Pose target = Irb120.Kinematics.Forward(new Joints(0, 0, 0, 0, -20, 0));
        bot.TransformTo(target.Position, target.Rotation);
        var kinds = Kinds(bot.GetWarnings());
        Assert.Contains(KinematicIssueKind.ConfigurationFlip, kinds);
        Assert.Contains(KinematicIssueKind.WristSingularity, kinds);
        Assert.All(bot.GetWarnings(), w => Assert.Equal(2, w.ActionId));
    }

    [Theory]
    [InlineData("ABB", "IRB 120", 0, 0, 0)]
    [InlineData("KUKA", "KR 6 R700 sixx", 0, -90, 90)]
    public void TurnAboutTheToolAxisWithAStraightWrist_SharedByAxes4And6WithoutFlip(string brand, string model, double j1, double j2, double j3)
    {
        // Axis 5 straight, axis 4 at 60°: turning the flange 10° about its own axis is a 10° change of A4 + A6. The nearest joints share
        // it (65°, −55°); axis 4 must not snap to 0° (a 60° jump reported as a configuration flip).
        Robot bot = Robot.Create("Bot", brand, model);
        bot.AxesTo(j1, j2, j3, 60, 0, -60);
        Pose target = bot.Model!.Kinematics.Forward(new Joints(j1, j2, j3, 60, 0, -50));
        bot.TransformTo(target.Position, target.Rotation);
        Assert.Equal([KinematicIssueKind.WristSingularity], Kinds(bot.GetWarnings().Where(w => w.ActionId == 2)));
        Joints after = bot.GetCurrentAxes()!.Value;
        Assert.True(after.IsSimilar(new Joints(j1, j2, j3, 65, 0, -55), 1e-6), $"joints after the turn: {after}");
    }

    [Fact]
    public void WarningsWithATool_NameTheToolTipPositionTheUserGave()
    {
        // The checks work on the flange, but the sentence must quote the TCP positions of the program, not flange coordinates.
        Robot bot = Robot.Create("Bot", "ABB", "IRB 120");
        bot.DefineTool("pen", new Vector(0, 50, 100), Rotation.FromAxisAngle(new Vector(1, 0, 0), 30));
        bot.AxesTo(0, 0, 0, 0, 90, 0);
        bot.AttachTool("pen");
        bot.MoveTo(2000, 0, 300);
        ProgramWarning w = Assert.Single(bot.GetWarnings());
        Assert.Equal("#4 MoveTo(2000,0,300); Unreachable: the target [2000, 0, 300] is out of reach of the ABB IRB 120.", w.ToString());
    }

    [Fact]
    public void TurnAboutTheToolTip_LineChecksFollowTheTipNotTheFlangeChord()
    {
        // The controller keeps the tool tip still while turning; the flange swings on an arc. The sampled path is the tip's, so every
        // place quoted is the tip's fixed position, and a pure turn has no length (no joint-speed estimate from the flange's chord).
        Robot bot = Robot.Create("Bot", "ABB", "IRB 120");
        bot.DefineTool("pen", new Vector(0, 0, 150), Rotation.Identity);
        bot.AxesTo(0, 10, 10, 0, 20, 0);
        bot.AttachTool("pen");
        Vector tip = bot.GetCurrentPosition()!.Value;
        bot.SpeedTo(1000);
        bot.Rotate(new Vector(0, 1, 0), -40);
        ProgramWarning w = Assert.Single(bot.GetWarnings(), x => x.ActionId == 5 && x.Kind == KinematicIssueKind.WristSingularity);
        Assert.Contains($"along the line, at {tip}, so axes 4 and 6 line up", w.Message, StringComparison.Ordinal);
        Assert.DoesNotContain(bot.GetWarnings(), x => x.Kind == KinematicIssueKind.JointSpeed);
        Assert.True(Vector.Distance(tip, bot.GetCurrentPosition()!.Value) < 1e-9);
    }

    [Fact]
    public void JointMotionToSameTarget_NoFlipWarning()
    {
        Robot bot = Robot.Create("Bot", "ABB", "IRB 1200-5/0.9");
        bot.AxesTo(0, 0, 0, 0, 30, 0);
        bot.MotionMode("joint");
        Pose target = bot.Model!.Kinematics.Forward(new Joints(0, 20, 0, 0, 30, 0));
        bot.TransformTo(target.Position, target.Rotation);
        Assert.Empty(bot.GetWarnings());
    }

    [Fact]
    public void FastLineOnSlowModel_JointSpeedWarning()
    {
        RobotModel slow = RobotModel.FromOpw("slow", "ABB", Irb120.Opw!.Value, Irb120.MinJoints, Irb120.MaxJoints, new Joints(1, 1, 1, 1, 1, 1));
        Robot bot = Robot.Create("Bot", RobotType.ABB, slow);
        bot.AxesTo(0, 10, 10, 0, 45, 0);
        bot.SpeedTo(500);
        bot.Move(0, 100, 0);
        ProgramWarning w = OnlyWarning(bot, KinematicIssueKind.JointSpeed, 3);
        Assert.Contains("above its maximum of 1°/s", w.Message);
    }

    [Fact]
    public void Compile_WithModel_ReplaysSameWarnings()
    {
        Robot bot = Robot.Create("Bot", "ABB", "IRB 120");
        bot.AxesTo(0, 0, 0, 0, 1, 0);
        bot.MoveTo(2000, 0, 300);
        bot.Wait(100);
        IReadOnlyList<ProgramWarning> issued = bot.GetWarnings();
        Assert.Equal([KinematicIssueKind.WristSingularity, KinematicIssueKind.Unreachable], Kinds(issued));
        foreach (RobotType language in new[] { RobotType.ABB, RobotType.HUMAN })
        {
            RobotProgram program = bot.Compile(language);
            Assert.Equal(issued, program.Warnings.Where(w => w.Kind is not null).ToList());
        }
        bot.ClearWarnings();
        Assert.Empty(bot.GetWarnings());
    }

    [Fact]
    public void StrictMode_Unreachable_RefusedStateAndIdsUnchanged()
    {
        Robot bot = Robot.Create("Bot", "ABB", "IRB 120");
        bot.StrictMode(true);
        Assert.True(bot.IsStrict);
        bot.AxesTo(0, 10, 10, 0, 45, 0);
        RobotState before = bot.GetCurrentState();
        var ex = Assert.Throws<ActionRefusedException>(() => bot.MoveTo(2000, 0, 300));
        Assert.StartsWith("strict mode: Unreachable: the target", ex.Reason);
        Assert.Equal((Point?)before.Position, bot.GetCurrentPosition());
        Assert.Equal(before.Axes, bot.GetCurrentAxes());
        Assert.Empty(bot.GetWarnings());
        Assert.Single(bot.GetProgramActions());
        bot.Move(0, 0, 10);
        Assert.Equal(2, bot.GetProgramActions()[1].Id);
        Assert.Equal(before.Position!.Value.Z + 10, bot.GetCurrentPosition()!.Value.Z, 9);
    }

    [Fact]
    public void StrictMode_JointLimitAndSingularity_Refused()
    {
        Robot bot = Robot.Create("Bot", "ABB", "IRB 120");
        bot.StrictMode(true);
        Assert.Throws<ActionRefusedException>(() => bot.AxesTo(0, 0, 95, 0, 30, 0));
        var ex = Assert.Throws<ActionRefusedException>(() => bot.AxesTo(0, 0, 0, 0, 1, 0));
        Assert.Contains("WristSingularity", ex.Reason);
        Assert.Null(bot.GetCurrentAxes());
        Assert.Null(bot.GetCurrentPosition());
        Assert.Empty(bot.GetProgramActions());
        bot.StrictMode(false);
        bot.AxesTo(0, 0, 0, 0, 1, 0);
        Assert.Equal(1, bot.GetProgramActions()[0].Id);
    }

    [Fact]
    public void StrictMode_DoWithRefusedStatement_IssuesNothing()
    {
        Robot bot = Robot.Create("Bot", "ABB", "IRB 120");
        bot.StrictMode(true);
        bot.AxesTo(0, 10, 10, 0, 45, 0);
        Assert.Throws<ActionRefusedException>(() => bot.Do("Move(0,0,10); MoveTo(2000,0,300); Wait(10);"));
        Assert.Single(bot.GetProgramActions());
    }

    [Fact]
    public void ArcThroughUnreachablePoint_WarnsWhereTheArcLeavesTheReach()
    {
        Robot bot = Robot.Create("Bot", "ABB", "IRB 120");
        bot.AxesTo(0, 10, 10, 0, 45, 0);
        Vector start = bot.GetCurrentPosition()!.Value;
        bot.ArcMotionTo(new Vector(2000, 0, start.Z), new Vector(start.X, start.Y + 20, start.Z));
        ProgramWarning w = Assert.Single(bot.GetWarnings());
        Assert.Equal(KinematicIssueKind.Unreachable, w.Kind);
        // The arc is followed from the start: it leaves the reach on its way to the through point.
        Assert.StartsWith("Unreachable: the arc leaves the reach of the ABB IRB 120 ", w.Message);
        Assert.Contains("% along the arc, at [", w.Message);
        Assert.NotNull(bot.GetCurrentAxes());
    }

    [Fact]
    public void JointMoveToACartesianTarget_AJointSwingsMoreThanHalfATurn_Warns()
    {
        // Axis 6 at 390° of its ±400°: turning the tool 30° more is only possible the other way round, 330° back.
        Robot bot = TurnToolInAJointMove(390, 30);

        ProgramWarning w = OnlyWarning(bot, KinematicIssueKind.LargeJointMove, 4);
        Assert.Equal("LargeJointMove: to reach this target in a joint move, joint 6 turns 330° (from 390° to 60°); make sure the tool and its cables have room to swing.", w.Message);
    }

    [Fact]
    public void JointMoveTurningAJointLessThanHalfATurn_NoWarning()
    {
        Robot bot = TurnToolInAJointMove(90, 170);

        Assert.Empty(bot.GetWarnings());
        Assert.Equal(170, Math.Abs(bot.GetCurrentAxes()!.Value.J6 - 90), 6);
    }

    [Fact]
    public void AxesTo_ExactlyAtTheWristSingularity_SaysStraightNotWithinZeroDegrees()
    {
        Robot bot = Robot.Create("Bot", "ABB", "IRB 120");
        bot.AxesTo(0, 0, 0, 0, 0, 0);

        ProgramWarning w = Assert.Single(bot.GetWarnings());
        Assert.Equal("WristSingularity: axis 5 is exactly straight at the target, so axes 4 and 6 line up and the controller cannot tell them apart; axes 4 and 6 may spin fast.", w.Message);
    }

    [Fact]
    public void AxesTo_NearTheWristSingularity_SaysHowFar()
    {
        Robot bot = Robot.Create("Bot", "ABB", "IRB 120");
        bot.AxesTo(0, 0, 0, 0, 1.5, 0);

        ProgramWarning w = Assert.Single(bot.GetWarnings());
        Assert.StartsWith("WristSingularity: axis 5 is only 1.5° from straight at the target", w.Message, StringComparison.Ordinal);
    }

    [Fact]
    public void AxesTo_WristCentreOnAxisOne_SaysOnTheLineNotZeroMillimetres()
    {
        // IRB 120: no offset between axes 1 and 2, so axis 1's singular line is the vertical through the base. Find the axis 3 angle
        // that puts the wrist centre (72 mm behind the flange) on it, by bisection on the wrist centre's X.
        RobotModel model = RobotModels.Get("IRB 120");
        Robot bot = Robot.Create("Bot", "ABB", "IRB 120");
        double WristX(double j3)
        {
            Pose flange = model.Kinematics.Forward(new Joints(0, 0, j3, 0, 45, 0));
            return (flange.Position - flange.Rotation * new Vector(0, 0, 72)).X;
        }
        double lo = -110, hi = 70;
        Assert.True(Math.Sign(WristX(lo)) != Math.Sign(WristX(hi)));
        for (int i = 0; i < 100; i++)
        {
            double mid = (lo + hi) / 2;
            if (Math.Sign(WristX(mid)) == Math.Sign(WristX(lo))) { lo = mid; } else { hi = mid; }
        }
        Joints j = new(0, 0, lo, 0, 45, 0);
        bot.AxesTo(j);

        ProgramWarning w = Assert.Single(bot.GetWarnings(), x => x.Kind == KinematicIssueKind.ShoulderSingularity);
        Assert.StartsWith("ShoulderSingularity: the wrist is right on axis 1's singular line at the target", w.Message, StringComparison.Ordinal);
    }
}
