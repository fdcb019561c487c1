namespace Machina.Tests.Kinematics;

/// <summary>Lines and arcs: the joints predicted (and written as KUKA Status/Turn or ABB confdata) are those reached along the path.</summary>
public class PathFollowingTests
{
    /// <summary>KR 6 R900 sixx with a tool 100 mm along the flange's X, tilted 30° about Y (issue 13's arc).</summary>
    private static Robot TiltedToolKuka()
    {
        Robot bot = Robot.Create("Bot", "KUKA", "KR 6 R900 sixx");
        bot.DefineTool("t", new Vector(100, 0, 0), Rotation.FromAxisAngle(new Vector(0, 1, 0), 30));
        bot.AttachTool("t");
        return bot;
    }

    private static readonly Pose TiltedTool = new(new Vector(100, 0, 0), Rotation.FromAxisAngle(new Vector(0, 1, 0), 30));

    /// <summary>Independent follower: the tool tip on the circle of centre (500, 0, 300), radius 100, from 90° to −90° every 1°.</summary>
    private static Joints FollowCircle(RobotModel model, Joints start, Rotation tcp)
    {
        Joints last = start;
        for (int deg = 89; deg >= -90; deg--)
        {
            double a = deg * Math.PI / 180;
            var tip = new Pose(new Vector(500 + 100 * Math.Cos(a), 100 * Math.Sin(a), 300), tcp);
            last = model.Kinematics.Closest(tip * TiltedTool.Inverse(), last) ?? throw new InvalidOperationException($"unreachable at {deg}°");
        }
        return last;
    }

    /// <summary>
    /// The tilted-tool KUKA after issue 13's arc, from (500, 100, 300) over (600, 0, 300) to (500, −100, 300): the robot, its joints
    /// at the start, and the joints an independent follower reaches at the end.
    /// </summary>
    private static (Robot Bot, Joints Start, Joints Followed) AfterTheArc()
    {
        Robot bot = TiltedToolKuka();
        bot.MoveTo(500, 100, 300);
        Joints start = bot.GetCurrentAxes()!.Value;
        bot.ArcMotionTo(600, 0, 300, 500, -100, 300);
        return (bot, start, FollowCircle(bot.Model!, start, bot.GetCurrentRotation()!.Value));
    }

    [Fact]
    public void ArcMotionTo_WristNearStraight_JointsFollowTheArcNotTheEndPointAlone()
    {
        (Robot bot, Joints start, Joints followed) = AfterTheArc();

        Joints after = bot.GetCurrentAxes()!.Value;
        Assert.True(after.IsSimilar(followed, 1e-6), $"predicted {after}, followed {followed}");
        // Along the circle axis 5 stays between 5° and 10° on the side it started on: no wrist flip.
        Assert.InRange(start.J5, 5, 10);
        Assert.InRange(after.J5, 5, 10);
        Assert.DoesNotContain(bot.GetWarnings(), w => w.Kind == KinematicIssueKind.ConfigurationFlip);
        string circ = Assert.Single(bot.Compile().Files[0].Lines, l => l.Contains("CIRC", StringComparison.Ordinal));
        Assert.Contains("S 'B010'", circ, StringComparison.Ordinal);
    }

    [Fact]
    public void JointMoveAfterAnArc_StartsFromTheFollowedJoints_NoHalfTurnOfTheWrist()
    {
        // Before, the PTP after the arc was solved from the end-point-only joints: its Status and Turn asked the arm, really at the
        // followed joints, to turn axes 4 and 6 by about 180°.
        (Robot bot, _, Joints followed) = AfterTheArc();
        bot.MotionMode("joint");
        bot.MoveTo(500, -100, 350);

        Joints afterPtp = bot.GetCurrentAxes()!.Value;
        for (int k = 0; k < Joints.Count; k++)
        {
            Assert.True(Math.Abs(afterPtp[k] - followed[k]) < 90, $"joint {k + 1} swings from {followed[k]} to {afterPtp[k]}");
        }
        Assert.Empty(bot.GetWarnings());
        string ptp = Assert.Single(bot.Compile().Files[0].Lines, l => l.Contains("PTP {E6POS", StringComparison.Ordinal));
        Assert.Contains("S 'B010'", ptp, StringComparison.Ordinal);
    }

    [Fact]
    public void MoveTo_LinePassingNearAStraightWrist_JointsFollowTheLine()
    {
        // The same tool, a line that passes 2° from the straight wrist: axis 4 turns 151° on the way, axis 5 keeps its sign. The solution
        // closest to the start joints at the end point alone has the wrist flipped (axis 5 negative), which the arm never reaches.
        Robot bot = TiltedToolKuka();
        bot.MoveTo(500, 100, 340);
        Joints start = bot.GetCurrentAxes()!.Value;
        bot.MoveTo(500, -100, 260);

        Joints after = bot.GetCurrentAxes()!.Value;
        Assert.True(start.J5 > 0 && after.J5 > 0, $"{start} -> {after}");
        Assert.Equal(-113.335, after.J4, 3);
        Assert.Equal([KinematicIssueKind.WristSingularity], bot.GetWarnings().Select(w => w.Kind));
        Assert.Contains("along the line", bot.GetWarnings()[0].Message, StringComparison.Ordinal);
    }

    [Fact]
    public void ArcMotionTo_CrossingAStraightWrist_WarnsWhereAlongTheArc()
    {
        // Tool 100 mm along the flange's Z, tilted 30°: on this circle axis 5 must go from −7.5° to +7.5°, which the arm can only do by flipping its wrist half-way.
        Robot bot = Robot.Create("Bot", "KUKA", "KR 6 R900 sixx");
        bot.DefineTool("t", new Vector(0, 0, 100), Rotation.FromAxisAngle(new Vector(0, 1, 0), 30));
        bot.AttachTool("t");
        bot.MoveTo(500, 100, 300);
        bot.ArcMotionTo(600, 0, 300, 500, -100, 300);

        ProgramWarning[] warnings = [.. bot.GetWarnings().Where(w => w.ActionId == 4)];
        ProgramWarning flip = Assert.Single(warnings, w => w.Kind == KinematicIssueKind.ConfigurationFlip);
        Assert.Contains("51% along the arc, at [599.921, -3.976, 300]", flip.Message, StringComparison.Ordinal);
        Assert.True(bot.GetCurrentAxes()!.Value.J5 > 0);
    }
}
