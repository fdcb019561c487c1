using Machina.Tests.Support;

namespace Machina.Tests.Core;

public class HelloRobotTests
{
    private static Robot IssueHelloRobot(List<ActionIssuedArgs>? events = null)
    {
        var bot = Robot.Create("HelloRobot", "ABB");
        if (events is not null)
        {
            bot.ActionIssued += (_, e) => events.Add(e);
        }
        ReferencePrograms.HelloRobot(bot);
        return bot;
    }

    [Fact]
    public void HelloRobot_IssuedOffline_CursorStatesMatchThePaper()
    {
        var events = new List<ActionIssuedArgs>();
        IssueHelloRobot(events);

        Assert.Equal(7, events.Count);
        Assert.Equal([1, 2, 3, 4, 5, 6, 7], events.Select(e => e.LastAction.Id));
        Assert.Null(events[0].Position);
        Assert.Equal(100, events[1].State.Speed);
        Assert.Equal(new Vector(400, 300, 500), events[2].Position);
        // Rotating -90° about world Y turns the downward tool (180° about Y) to point along -X... quaternion [0.7071, 0, 0.7071, 0].
        Rotation r = events[3].Rotation!.Value;
        Assert.Equal(0.70710678, r.W, 6);
        Assert.Equal(0, r.X, 9);
        Assert.Equal(0.70710678, r.Y, 6);
        Assert.Equal(0, r.Z, 9);
        Assert.Equal(new Vector(400, 300, 750), events[4].Position);
        Assert.Equal(new Joints(0, 0, 0, 0, 90, 0), events[6].Axes);
        Assert.Null(events[6].Position);
        Assert.Null(events[6].Rotation);
    }

    [Fact]
    public void HelloRobot_RotateEvent_JsonMatchesOriginalBridgeShape()
    {
        var events = new List<ActionIssuedArgs>();
        IssueHelloRobot(events);

        Assert.Equal(
            "{\"event\":\"action-issued\",\"last\":\"Rotate(0,1,0,-90);\",\"id\":4,\"pos\":[400,300,500],\"ori\":[0,0,-1,0,1,0],\"quat\":[0.7071,0,0.7071,0],\"axes\":null,\"extax\":null,\"conf\":null}",
            events[3].ToJsonString());
    }

    [Fact]
    public void HelloRobot_MachinaListing_ParsesBackToTheSameActions()
    {
        var bot = IssueHelloRobot();
        RobotProgram program = bot.Compile(RobotType.MACHINA);
        string text = program.Files[0].ToText();

        IReadOnlyList<RobotAction> parsed = Instructions.Parse(text);

        Assert.Equal(bot.GetProgramActions(), parsed);
        Assert.Contains("Rotate(0,1,0,-90);", program.Files[0].Lines);
    }

    [Fact]
    public void HelloRobot_HumanListing_HasOneNumberedLinePerAction()
    {
        var bot = IssueHelloRobot();
        var lines = bot.Compile(RobotType.HUMAN).Files[0].Lines.Where(l => l.StartsWith('[')).ToArray();

        Assert.Equal(
            [
                "[0] Display message \"Hello Robot!\"",
                "[1] Set motion speed to 100 mm/s or deg/s",
                "[2] Move to [400, 300, 500] mm",
                "[3] Rotate -90 deg around [0, 1, 0]",
                "[4] Move [0, 0, 250] mm",
                "[5] Wait 2000 ms",
                "[6] Set joint rotations to [0, 0, 0, 0, 90, 0] deg",
            ],
            lines);
    }
}

public class ReferenceProgramTests
{
    [Theory]
    [InlineData("HelloRobot")]
    [InlineData("SquarePushPop")]
    [InlineData("Rotations")]
    [InlineData("JointsToolsIO")]
    [InlineData("Print3D")]
    public void ReferenceProgram_MachinaListing_RoundTripsThroughTheParser(string name)
    {
        var bot = Machina.Tests.Support.ReferencePrograms.Issue(name, RobotType.MACHINA);
        var text = bot.Compile().Files[0].ToText();

        Assert.Equal(bot.GetProgramActions(), Instructions.Parse(text));
    }
}
