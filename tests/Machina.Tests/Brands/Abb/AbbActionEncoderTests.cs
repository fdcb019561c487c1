namespace Machina.Tests.Brands.Abb;

public class AbbActionEncoderTests
{
    private readonly RobotCursor _cursor = new();
    private int _nextId = 1;

    /// <summary>Applies the action to the cursor with the next id and returns the wire text of its requests.</summary>
    private string Wire(RobotAction action)
    {
        action.Id = _nextId++;
        Assert.Null(_cursor.TryApply(action));
        var requests = new List<AbbRequest>();
        AbbActionEncoder.Encode(action, _cursor, requests);
        return string.Concat(requests.Select(r => r.ToWireText()));
    }

    [Fact]
    public void Encode_MotionActions_ExactWireText()
    {
        Assert.Equal("@1 1 400 0 500 0 0 1 0;", Wire(new ActionTransformation(new Vector(400, 0, 500), Rotation.FromQuaternion(0, 0, 1, 0), false, true)));
        Assert.Equal("@2 1 450 0 500 0 0 1 0;", Wire(new ActionTranslation(new Vector(50, 0, 0), true)));
        Wire(new ActionMotionMode(MotionType.Joint));
        Assert.Equal("@4 2 450 0 450 0 0 1 0;", Wire(new ActionTranslation(new Vector(0, 0, -50), true)));
        Assert.Equal("@5 3 0 0 0 0 90 0;", Wire(new ActionAxes(new Joints(0, 0, 0, 0, 90, 0), false)));
    }

    [Fact]
    public void Encode_Settings_ExactWireText()
    {
        Assert.Equal("@1 4 100;", Wire(new ActionSpeed(100, false)));
        Assert.Equal("@2 13 0.03;", Wire(new ActionAcceleration(30, false)));
        Assert.Equal("@3 5 2;", Wire(new ActionPrecision(2, false)));
        Assert.Equal("@4 6 1.5;", Wire(new ActionWait(1500)));
        Assert.Equal("@5 7 \"Hello world!\";", Wire(new ActionMessage("Hello world!")));
        Assert.Equal("@6 10 \"DO_15\" 1;", Wire(new ActionIODigital("DO_15", true, false)));
        Assert.Equal("@7 11 \"AO_1\" 0.5;", Wire(new ActionIOAnalog("AO_1", 0.5, false)));
        Assert.Equal("@8 18 300 0 300 1 0 0 0;", Wire(new ActionCustomCode("18 300 0 300 1 0 0 0", false)));
    }

    [Fact]
    public void Encode_Tools_DefineSendsNothingAttachSendsTool()
    {
        Assert.Equal("", Wire(new ActionDefineTool(Tool.Create("pen", new Vector(0, 0, 100), Rotation.Identity, 1, new Vector(0, 0, 50)))));
        Assert.Equal("@2 8 0 0 100 1 0 0 0 1 0 0 50;", Wire(new ActionAttachTool("pen")));
        Assert.Equal("@3 9;", Wire(new ActionDetachTool()));
    }

    [Fact]
    public void Encode_PopSettings_OneRequestPerChangeOnlyLastCarriesId()
    {
        Assert.Equal("", Wire(new ActionPushPop(true)));
        Wire(new ActionSpeed(100, false));
        Wire(new ActionPrecision(1, false));
        Assert.Equal("@0 4 20;@4 5 5;", Wire(new ActionPushPop(false)));
    }

    [Fact]
    public void Encode_ExternalAxisAll_RobTargetWithIdZeroThenJointTarget()
    {
        Assert.Equal("@0 15 1800 9E9 9E9 9E9 9E9 9E9;@1 16 1800 9E9 9E9 9E9 9E9 9E9;", Wire(new ActionExternalAxis(1, 1800, ExternalAxesTarget.All, false)));
        Assert.Equal("@2 15 1800 9E9 5 9E9 9E9 9E9;", Wire(new ActionExternalAxis(3, 5, ExternalAxesTarget.Cartesian, false)));
    }

    [Fact]
    public void Encode_NotStreamable_SendsNothing()
    {
        Assert.Equal("", Wire(new ActionComment("note")));
        Assert.Equal("", Wire(new ActionMotionMode(MotionType.Joint)));
    }
}
