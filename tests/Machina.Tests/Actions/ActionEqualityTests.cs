namespace Machina.Tests.Actions;

/// <summary>Actions compare by what they say, never by their id.</summary>
public class ActionEqualityTests
{
    [Fact]
    public void Equals_SameValuesDifferentIds_AreEqual()
    {
        var bot = Robot.Create("EqBot", RobotType.ABB);
        bot.MoveTo(1, 2, 3);
        RobotAction issued = bot.GetProgramActions()[0];
        var fresh = new ActionTranslation(new Vector(1, 2, 3), false);

        Assert.Equal(1, issued.Id);
        Assert.Equal(-1, fresh.Id);
        Assert.Equal(fresh, issued);
        Assert.Equal(fresh.GetHashCode(), issued.GetHashCode());
    }

    [Fact]
    public void Equals_RelativeVersusAbsolute_AreDifferent()
    {
        Assert.NotEqual<RobotAction>(new ActionSpeed(10, true), new ActionSpeed(10, false));
        Assert.NotEqual<RobotAction>(new ActionTranslation(Vector.XAxis, true), new ActionTranslation(Vector.XAxis, false));
        Assert.NotEqual<RobotAction>(new ActionRotation(Vector.ZAxis, 10, true), new ActionRotation(Vector.ZAxis, 10, false));
    }

    [Fact]
    public void Equals_DifferentTypesSameShape_AreDifferent()
    {
        Assert.NotEqual<RobotAction>(new ActionSpeed(10, true), new ActionAcceleration(10, true));
        Assert.NotEqual<RobotAction>(new ActionMessage("x"), new ActionComment("x"));
        Assert.NotEqual<RobotAction>(new ActionPushPop(true), new ActionPushPop(false));
    }

    [Fact]
    public void Equals_RotationsWithUnnormalisedAxis_AreEqual()
    {
        Assert.Equal<RobotAction>(new ActionRotation(new Vector(0, 0, 5), 30, true), new ActionRotation(new Vector(0, 0, 1), 30, true));
        Assert.NotEqual<RobotAction>(new ActionRotation(Vector.ZAxis, 30, true), new ActionRotation(Vector.ZAxis, 30.001, true));
    }

    [Fact]
    public void Equals_ToolsDifferingInWeight_AreDifferent()
    {
        var a = new ActionDefineTool(Tool.Create("t", new Vector(0, 0, 10), Rotation.Identity, 1, Vector.Zero));
        var b = new ActionDefineTool(Tool.Create("t", new Vector(0, 0, 10), Rotation.Identity, 2, Vector.Zero));
        var c = new ActionDefineTool(Tool.Create("t", new Vector(0, 0, 10), Rotation.Identity, 1, Vector.Zero));

        Assert.NotEqual(a, b);
        Assert.Equal(a, c);
    }

    [Fact]
    public void Equals_ReissuedSameObject_GetsItsOwnCopyAndId()
    {
        var bot = Robot.Create("EqBot", RobotType.ABB);
        var wait = new ActionWait(10);
        bot.Issue(wait);
        bot.Issue(wait);

        IReadOnlyList<RobotAction> actions = bot.GetProgramActions();
        Assert.Equal(1, actions[0].Id);
        Assert.Equal(2, actions[1].Id);
        Assert.Equal(1, wait.Id);
        Assert.NotSame(actions[0], actions[1]);
        Assert.Equal(actions[0], actions[1]);
    }
}
