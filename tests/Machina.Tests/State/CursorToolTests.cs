namespace Machina.Tests.State;

/// <summary>Tool definition, attachment and detachment move the TCP exactly (the original's detach bug 11 must not exist).</summary>
public class CursorToolTests
{
    private static readonly Vector Down = new(0, 0, -1);

    private static Robot FlangeAt100_0_200WithRotatedTool()
    {
        var bot = PoseAssert.AtFlipped(100, 0, 200);
        bot.DefineTool("rotated", new Vector(0, 50, 0), Rotation.FromAxisAngle(Vector.ZAxis, 90));
        return bot;
    }

    [Fact]
    public void AttachTool_RotatedTool_MovesTcpToTheTip()
    {
        var bot = FlangeAt100_0_200WithRotatedTool();
        bot.AttachTool("rotated");

        // Ry(180) keeps Y, so the tip (0, 50, 0) in the flange frame is +50 along world Y.
        PoseAssert.Near(new Vector(100, 50, 200), bot.GetCurrentPosition());
        // Ry(180)·Rz(90): TCP X = Ry(180)·(+Y) = +Y; Z still down.
        PoseAssert.Axes(new Vector(0, 1, 0), Down, bot.GetCurrentRotation());
        Assert.Equal("rotated", bot.GetCurrentTool()!.Name);
    }

    [Fact]
    public void DetachTool_RotatedTool_RestoresTheFlangeExactly()
    {
        var bot = FlangeAt100_0_200WithRotatedTool();
        bot.AttachTool("rotated");
        bot.DetachTool();

        PoseAssert.Near(new Vector(100, 0, 200), bot.GetCurrentPosition()); // the original gave [50, 50, 200]
        Assert.True(bot.GetCurrentRotation()!.Value.IsSimilar(Rotation.FlippedAroundY, 1e-9));
        Assert.Null(bot.GetCurrentTool());
    }

    [Fact]
    public void DetachTool_AfterMovesAndRotations_GivesTheFlangeOfTheCurrentTcp()
    {
        var bot = FlangeAt100_0_200WithRotatedTool();
        bot.AttachTool("rotated");
        bot.Move(0, 0, 100); // TCP (100, 50, 300)
        bot.Rotate(0, 0, 1, 90); // about world Z, around the TCP
        bot.DetachTool();

        // Flange rotation = Rz(90)·Ry(180); tip offset in world = that · (0, 50, 0) = Rz(90)·(0, 50, 0) = (−50, 0, 0).
        PoseAssert.Near(new Vector(150, 50, 300), bot.GetCurrentPosition());
        PoseAssert.Axes(new Vector(0, -1, 0), Down, bot.GetCurrentRotation());
    }

    [Fact]
    public void AttachTool_SecondTool_ReplacesTheFirstFromTheFlange()
    {
        var bot = FlangeAt100_0_200WithRotatedTool();
        bot.DefineTool("long", new Vector(0, 0, 100), Rotation.Identity);
        bot.AttachTool("rotated");
        bot.AttachTool("long");

        PoseAssert.Near(new Vector(100, 0, 100), bot.GetCurrentPosition());
        Assert.True(bot.GetCurrentRotation()!.Value.IsSimilar(Rotation.FlippedAroundY, 1e-9));
        Assert.Equal("long", bot.GetCurrentTool()!.Name);

        bot.DetachTool();
        PoseAssert.Near(new Vector(100, 0, 200), bot.GetCurrentPosition());
    }

    [Fact]
    public void AttachTool_Unknown_IsRefusedAndNamesTheDefinedTools()
    {
        var bot = FlangeAt100_0_200WithRotatedTool();
        RobotState before = bot.GetCurrentState();

        var ex = Assert.Throws<ActionRefusedException>(() => bot.AttachTool("gripper"));

        Assert.Equal("no tool named \"gripper\" is defined (defined tools: rotated); use DefineTool first.", ex.Reason);
        Assert.Equal(before.Position, bot.GetCurrentState().Position);
        Assert.Null(bot.GetCurrentTool());
        Assert.Equal(2, bot.GetProgramActions().Count);
    }

    [Fact]
    public void AttachTool_NothingDefined_SaysNoToolsAreDefined()
    {
        var bot = Robot.Create("Empty", RobotType.ABB);

        var ex = Assert.Throws<ActionRefusedException>(() => bot.AttachTool("pen"));

        Assert.Equal("Cannot apply \"AttachTool(\"pen\");\": no tool named \"pen\" is defined (no tools are defined yet); use DefineTool first.", ex.Message);
    }

    [Fact]
    public void DetachTool_NoToolAttached_IsANoOpThatIsIssued()
    {
        var bot = PoseAssert.AtFlipped(1, 2, 3);

        Assert.True(bot.DetachTool());

        Assert.Equal(new Point(1, 2, 3), bot.GetCurrentPosition());
        Assert.Equal(new ActionDetachTool(), bot.GetProgramActions()[1]);
        Assert.Equal(2, bot.GetProgramActions()[1].Id);
    }

    [Fact]
    public void AttachTool_PoseUnknown_SetsTheToolWithoutMovingAndWarns()
    {
        var bot = Robot.Create("Blind", RobotType.ABB);
        var log = new List<LogEntry>();
        bot.Logger.Logged += (_, e) => log.Add(e);
        bot.DefineTool("pen", new Vector(0, 0, 50), Rotation.Identity);

        bot.AttachTool("pen");

        Assert.Null(bot.GetCurrentPosition());
        Assert.Equal("pen", bot.GetCurrentTool()!.Name);
        Assert.Contains(log, e => e.Level == LogLevel.WARNING && e.Message.Contains("tool pose is unknown"));
    }

    [Fact]
    public void DefineTool_SameNameTwice_ReplacesTheDefinitionAndWarns()
    {
        var bot = Robot.Create("Twice", RobotType.ABB);
        var log = new List<LogEntry>();
        bot.Logger.Logged += (_, e) => log.Add(e);
        bot.DefineTool("pen", new Vector(0, 0, 50), Rotation.Identity);
        bot.DefineTool("pen", new Vector(0, 0, 80), Rotation.Identity);

        Assert.Equal(new Vector(0, 0, 80), bot.GetCurrentState().DefinedTools["pen"].TcpPosition);
        Assert.Single(log, e => e.Message.Contains("already defined"));
    }

    [Fact]
    public void DefineTool_ThreePointOverload_WeighsOneKiloWithCogHalfway()
    {
        Tool tool = Tool.Create("pen", new Vector(0, 0, 50), Rotation.Identity);

        Assert.Equal(1, tool.Weight);
        Assert.Equal(new Vector(0, 0, 25), tool.CenterOfGravity);
        Assert.Equal("Tool[\"pen\", Tip[0, 0, 50], Orientation[[1, 0, 0], [0, 1, 0], [0, 0, 1]], 1 kg]", tool.ToString());
    }

    [Theory]
    [InlineData("")]
    [InlineData("9lives")]
    [InlineData("_x")]
    [InlineData("a b")]
    [InlineData("a\"b")]
    public void DefineTool_BadName_IsRefusedBeforeIssuing(string name)
    {
        var bot = Robot.Create("Names", RobotType.ABB);

        var ex = Assert.Throws<ArgumentException>(() => bot.DefineTool(name, Vector.Zero, Rotation.Identity));

        Assert.Equal("name", ex.ParamName);
        Assert.Empty(bot.GetProgramActions());
    }

    [Fact]
    public void DefineTool_NegativeWeight_IsRefused()
    {
        var ex = Assert.Throws<ArgumentException>(() => Tool.Create("t", Vector.Zero, Rotation.Identity, -1, Vector.Zero));

        Assert.Equal("weightKg", ex.ParamName);
    }

    [Fact]
    public void Move_WithToolInLocalFrame_UsesTheTcpFrame()
    {
        var bot = FlangeAt100_0_200WithRotatedTool();
        bot.AttachTool("rotated");
        bot.Coordinates(ReferenceCS.Local);
        bot.Move(10, 0, 0); // TCP X = world +Y

        PoseAssert.Near(new Vector(100, 60, 200), bot.GetCurrentPosition());
    }
}
