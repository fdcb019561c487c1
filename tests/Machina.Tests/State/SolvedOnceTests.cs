namespace Machina.Tests.State;

/// <summary>
/// A robot with a model solves a Cartesian motion once: a second cursor applying the same action from the same state reuses the
/// joints and issues, and a cursor starting anywhere else solves again (the cache never hands out another state's joints).
/// </summary>
public class SolvedOnceTests
{
    private static RobotCursor At(RobotModel model, Joints axes)
    {
        var cursor = new RobotCursor { Model = model };
        Pose tcp = model.Kinematics.Forward(axes);
        cursor.ResetToReported(tcp.Position, tcp.Rotation, axes, null);
        return cursor;
    }

    [Fact]
    public void SameStart_ReusesTheSolution_OtherStart_SolvesAgain()
    {
        RobotModel model = RobotModels.Get("IRB 120");
        var move = new ActionTranslation(new Vector(0, 0, -50), true);
        RobotCursor issue = At(model, new Joints(0, 0, 0, 0, 90, 0));
        RobotCursor release = At(model, new Joints(0, 0, 0, 0, 90, 0));
        RobotCursor elsewhere = At(model, new Joints(30, 10, 10, 0, 70, 0));

        Assert.Null(issue.TryApply(move));
        SolvedPose first = Assert.IsType<SolvedPose>(move.Solved);
        Assert.Null(release.TryApply(move));
        Assert.Same(first, move.Solved); // reused, not solved again
        Assert.Equal(issue.Axes, release.Axes);
        Assert.Null(elsewhere.TryApply(move));
        Assert.NotSame(first, move.Solved);

        // Each cursor's joints are its own target's solution: the forward kinematics give back its TCP target.
        foreach (RobotCursor c in new[] { issue, release, elsewhere })
        {
            Pose reached = model.Kinematics.Forward(c.Axes!.Value);
            Assert.True(reached.Position.IsSimilar(c.Position!.Value, 1e-6), $"{reached.Position} vs {c.Position}");
        }
        Assert.False(elsewhere.Position!.Value.IsSimilar(issue.Position!.Value, 1));
    }

    [Fact]
    public void SamePose_OtherJoints_SolvesAgain_AndKeepsItsOwnConfiguration()
    {
        // The same TCP pose reached with the elbow up and with the elbow down: a line from each must stay in its own configuration.
        RobotModel model = RobotModels.Get("IRB 120");
        Joints up = new(10, 20, 10, 30, 40, 50);
        Pose tcp = model.Kinematics.Forward(up);
        Joints down = OtherSolution(model, null, tcp, up);
        var issue = new RobotCursor { Model = model };
        issue.ResetToReported(tcp.Position, tcp.Rotation, up, null);
        var other = new RobotCursor { Model = model };
        other.ResetToReported(tcp.Position, tcp.Rotation, down, null);
        var move = new ActionTranslation(new Vector(0, 0, -10), true);

        Assert.Null(issue.TryApply(move));
        SolvedPose first = Assert.IsType<SolvedPose>(move.Solved);
        Assert.Null(other.TryApply(move));

        Assert.NotSame(first, move.Solved);
        Assert.Equal(issue.Position, other.Position);
        Assert.Equal(model.Kinematics.ConfigurationOf(up), model.Kinematics.ConfigurationOf(issue.Axes!.Value));
        Assert.Equal(model.Kinematics.ConfigurationOf(down), model.Kinematics.ConfigurationOf(other.Axes!.Value));
        Assert.NotEqual(model.Kinematics.ConfigurationOf(issue.Axes!.Value), model.Kinematics.ConfigurationOf(other.Axes!.Value));
    }

    [Fact]
    public void Key_TellsZeroFromNegativeZero_AndComparesTheToolsTipNotItsName()
    {
        RobotModel model = RobotModels.Get("IRB 120");
        Tool pen = Tool.Create("pen", new Vector(0, 0, 100), Rotation.Identity);
        Tool samePenOtherName = Tool.Create("marker", new Vector(0, 0, 100), Rotation.Identity);
        Tool longer = Tool.Create("pen", new Vector(0, 0, 100.000001), Rotation.Identity);
        PoseSolveKey Key(double x, Tool? tool) =>
            new(model, new Joints(0, 0, 0, 0, 90, 0), new Vector(x, 0, 500), Rotation.FlippedAroundY, tool, null, null, MotionType.Linear, 100);

        Assert.True(Key(0.0, pen) == Key(0.0, samePenOtherName));
        Assert.False(Key(0.0, pen) == Key(-0.0, pen));
        Assert.False(Key(0.0, pen) == Key(0.0, longer));
        Assert.False(Key(0.0, pen) == Key(0.0, null));
        Assert.False(Key(0.0, null) == new PoseSolveKey(model, null, new Vector(0, 0, 500), Rotation.FlippedAroundY, null, null, null, MotionType.Linear, 100));
        Assert.False(Key(0.0, null) == new PoseSolveKey(model, new Joints(0, 0, 0, 0, 90, 0), new Vector(0, 0, 500), Rotation.FlippedAroundY, null, null, null, MotionType.Joint, 100));
        Assert.False(Key(0.0, null) == new PoseSolveKey(model, new Joints(0, 0, 0, 0, 90, 0), new Vector(0, 0, 500), Rotation.FlippedAroundY, null, null, null, MotionType.Linear, 100.5));
        Assert.False(Key(0.0, null) == new PoseSolveKey(RobotModels.Get("IRB 1600-8/1.45"), new Joints(0, 0, 0, 0, 90, 0), new Vector(0, 0, 500), Rotation.FlippedAroundY, null, null, null, MotionType.Linear, 100));
    }

    /// <summary>
    /// Seeded random motions (lines, joint moves, rotations, transformations, arcs, tools, speeds, strict and lenient) on three
    /// arms: the cursor that may reuse the first cursor's solution ends every step exactly where a cursor solving everything
    /// itself ends (joints bit for bit, the same issues, the same refusals), while the first cursor is now and then put on another
    /// joint solution of the same pose.
    /// </summary>
    [Theory]
    [InlineData("IRB 120", 2201)]
    [InlineData("KR 6 R900-2", 2202)]
    [InlineData("UR5e", 2203)]
    public void RandomMotions_ReusedSolutionIsWhatAFreshSolveGives(string modelName, int seed)
    {
        RobotModel model = RobotModels.Get(modelName);
        var random = new Random(seed);
        Joints home = model.Brand == "UR" ? new Joints(10, -80, 90, -100, -90, 20) : new Joints(5, 10, 20, 10, 60, 10);
        RobotCursor first = At(model, home), reusing = At(model, home), fresh = At(model, home);
        int hits = 0, misses = 0;
        for (int step = 0; step < 600; step++)
        {
            bool strict = step % 200 >= 100;
            first.Strict = reusing.Strict = fresh.Strict = strict;
            // The first cursor starts where the others are (as the issue cursor before the release cursor), or now and then on
            // another solution of the same pose, or a hair away from it: its solution must not leak to the others.
            first.CopyFrom(reusing);
            if (random.Next(6) == 0 && reusing.Position is Vector p && reusing.Rotation is Rotation r && reusing.Axes is Joints j)
            {
                Joints elsewhere = random.Next(2) == 0 ? OtherSolution(model, first.Tool, new Pose(p, r), j) : j with { J6 = j.J6 + 1e-9 };
                first.SetLivePose(p, r, elsewhere, null);
            }
            RobotAction action = RandomAction(random);
            first.TryApply(action);
            SolvedPose? afterFirst = action.Solved;
            string? reused = reusing.TryApply(action);
            if (afterFirst is not null)
            {
                if (ReferenceEquals(afterFirst, action.Solved))
                {
                    hits++;
                }
                else
                {
                    misses++;
                }
            }
            RobotAction copy = action with { };
            copy.Solved = null;
            string? solved = fresh.TryApply(copy);

            string where = $"step {step}: {action}";
            Assert.Equal(solved, reused);
            Assert.True(Bits(fresh.Axes) == Bits(reusing.Axes), $"{where}: joints {reusing.Axes} vs a fresh solve's {fresh.Axes}");
            Assert.Equal(fresh.Position, reusing.Position);
            Assert.Equal(fresh.LastIssues.Select(i => i.ToString()), reusing.LastIssues.Select(i => i.ToString()));
            if (reusing.Axes is null && random.Next(2) == 0)
            {
                // Lost (out of reach): all three start again from home.
                foreach (RobotCursor c in new[] { first, reusing, fresh })
                {
                    Pose tcp = model.Kinematics.Forward(home);
                    c.ResetToReported(tcp.Position, tcp.Rotation, home, null);
                }
            }
        }
        Assert.InRange(hits, 100, 600);
        Assert.InRange(misses, 5, 600);
    }

    private static RobotAction RandomAction(Random random)
    {
        double D(double range) => Math.Round((random.NextDouble() * 2 - 1) * range, random.Next(3));
        return random.Next(12) switch
        {
            0 => new ActionMotionMode(random.Next(2) == 0 ? MotionType.Linear : MotionType.Joint),
            1 => new ActionSpeed(random.Next(3) == 0 ? 5000 : 100, false),
            2 => new ActionDefineTool(Tool.Create(random.Next(2) == 0 ? "a" : "b", new Vector(0, 0, random.Next(2) == 0 ? 100 : 50), Rotation.Identity)),
            3 => new ActionAttachTool(random.Next(2) == 0 ? "a" : "b"),
            4 => new ActionRotation(new Vector(D(1), D(1), 1), D(30), true),
            5 => new ActionTransformation(new Vector(D(50), D(50), D(50)), new Rotation(new Vector(1, D(1), 0), D(20)), true, random.Next(2) == 0),
            6 => new ActionArcMotion(new Plane(new Vector(D(30), D(30), D(5)), Rotation.Identity), new Plane(new Vector(D(60), D(60), D(5)), Rotation.Identity), true, true),
            7 => new ActionTranslation(new Vector(random.Next(2) == 0 ? -0.0 : 0.0, D(1), 0), true),
            8 => new ActionRotation(Rotation.FlippedAroundY, false),
            _ => new ActionTranslation(new Vector(D(80), D(80), D(80)), true),
        };
    }

    /// <summary>Another joint solution of <paramref name="tcp"/> within the limits (<paramref name="not"/> itself when there is none).</summary>
    private static Joints OtherSolution(RobotModel model, Tool? tool, Pose tcp, Joints not)
    {
        Span<Joints> all = stackalloc Joints[8];
        Pose flange = tool is null ? tcp : tcp * new Pose(tool.TcpPosition, tool.TcpOrientation).Inverse();
        int n = model.Kinematics.Inverse(flange, all);
        for (int i = 0; i < n; i++)
        {
            if (model.Kinematics.ConfigurationOf(all[i]) != model.Kinematics.ConfigurationOf(not))
            {
                return all[i];
            }
        }
        return not;
    }

    private static string Bits(Joints? j) => j is Joints v
        ? string.Join(",", new[] { v.J1, v.J2, v.J3, v.J4, v.J5, v.J6 }.Select(BitConverter.DoubleToInt64Bits))
        : "none";
}
