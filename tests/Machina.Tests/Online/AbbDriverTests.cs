namespace Machina.Tests.Online;

public class AbbDriverTests
{
    [Theory]
    [InlineData(1, 1)]
    [InlineData(8_388_608, 8_388_608)]
    [InlineData(8_388_609, 1)]
    [InlineData(16_777_217, 1)]
    [InlineData(20_000_000, 3_222_784)]
    public void WireId_BeyondWhatRapidReadsExactly_Wraps(int actionId, int wireId) =>
        Assert.Equal(wireId, AbbDriver.WireId(actionId));

    [Fact]
    public void Translate_PopWithoutChanges_SendsNothing()
    {
        var cursor = new RobotCursor();
        Assert.Null(cursor.TryApply(new ActionPushPop(true)));
        Assert.Null(cursor.TryApply(new ActionPushPop(false)));
        var requests = new AbbRequest[AbbActionTranslator.MaxRequests];

        Assert.Equal(0, AbbActionTranslator.Translate(new ActionPushPop(false), cursor, 5, requests));
    }

    [Fact]
    public void Translate_ArmAngle_SendsRobTargetAxisOne()
    {
        var cursor = new RobotCursor();
        var action = new ActionArmAngle(30, false);
        Assert.Null(cursor.TryApply(action));
        var requests = new AbbRequest[AbbActionTranslator.MaxRequests];

        Assert.Equal(1, AbbActionTranslator.Translate(action, cursor, 9, requests));
        Assert.Equal("@9 15 30 9E9 9E9 9E9 9E9 9E9;", requests[0].ToWireText());
    }

    [Fact]
    public void Translate_ArcMotion_SendsEndPoseAndThroughPoint()
    {
        var cursor = new RobotCursor();
        Assert.Null(cursor.TryApply(new ActionTranslation(new Vector(500, 0, 500), false)));
        var arc = new ActionArcMotion(new Plane(new Vector(600, 100, 500), Rotation.FlippedAroundY), new Plane(new Vector(500, 200, 500), Rotation.FlippedAroundY), false, true);
        Assert.Null(cursor.TryApply(arc));
        var requests = new AbbRequest[AbbActionTranslator.MaxRequests];

        Assert.Equal(1, AbbActionTranslator.Translate(arc, cursor, 4, requests));
        Assert.Equal("@4 30 500 200 500 0 0 1 0 600 100 500;", requests[0].ToWireText());
    }
}
