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
}
