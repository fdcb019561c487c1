namespace Machina.Tests.State;

/// <summary>Debug texts of the cursor (spec §6.5), the state snapshot and the settings (spec §6.3).</summary>
public class CursorTextTests
{
    [Fact]
    public void ToString_NewCursor_ShowsTheInitialState()
    {
        Assert.Equal("Linear pnull r[0, 0, 1, 0] jnull a30 v20 p5", new RobotCursor().ToString());
    }

    [Fact]
    public void ToString_CursorWithToolAndPose_ShowsThem()
    {
        var cursor = new RobotCursor();
        cursor.TryApply(new ActionTranslation(new Vector(1, 2, 3), false));
        cursor.TryApply(new ActionDefineTool(Tool.Create("pen", new Vector(0, 0, 10), Rotation.Identity)));
        cursor.TryApply(new ActionAttachTool("pen"));

        Assert.Equal("Linear p[1, 2, -7] r[0, 0, 1, 0] jnull a30 v20 p5 tpen", cursor.ToString());
    }

    [Fact]
    public void ToString_State_ShowsPoseAndSettings()
    {
        var bot = Robot.Create("Bot", RobotType.ABB);
        bot.MoveTo(400, 300, 500);

        Assert.Equal("State[position [400, 300, 500], rotation [0, 0, 1, 0], axes unknown, speed 20 mm/s, acceleration 30 mm/s², precision 5 mm, linear motion, world frame]", bot.GetCurrentState().ToString());
    }

    [Fact]
    public void TryApply_Refusal_ReturnsReasonAndChangesNothing()
    {
        var cursor = new RobotCursor();
        string before = cursor.ToString();

        string? reason = cursor.TryApply(new ActionRotation(Vector.ZAxis, 10, false));

        Assert.Equal("the tool position is not known yet; use MoveTo or TransformTo first (RotateTo only turns the tool around its tip).", reason);
        Assert.Equal(before, cursor.ToString());
        Assert.Null(cursor.LastAction);
    }

    [Fact]
    public void CopyFrom_AnotherCursor_IsIndependent()
    {
        var a = new RobotCursor();
        a.TryApply(new ActionTranslation(new Vector(1, 2, 3), false));
        a.TryApply(new ActionPushPop(true));
        a.TryApply(new ActionIODigital("1", true, false));
        var b = new RobotCursor();
        b.CopyFrom(a);

        a.TryApply(new ActionPushPop(false));
        a.TryApply(new ActionIODigital("1", false, false));

        Assert.Single(b.SettingsStack);
        Assert.True(b.DigitalOutputs["1"]);
        Assert.Equal(new Vector(1, 2, 3), b.Position);
    }
}
