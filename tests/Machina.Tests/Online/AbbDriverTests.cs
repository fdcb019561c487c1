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

public class DriverModulesTests
{
    [Fact]
    public void GetDeviceDriverModules_Abb_FillsHostAndPorts()
    {
        var bot = Robot.Create("Modules", "ABB");
        var files = bot.GetDeviceDriverModules(new Dictionary<string, string> { ["HOSTNAME"] = "192.168.125.1", ["PORT"] = "7000" });

        Assert.Equal(["machina_abb_driver.mod", "machina_abb_driver.pgf", "machina_abb_monitor.mod", "machina_abb_monitor.pgf"], files.Keys.Order());
        Assert.Contains("192.168.125.1", files["machina_abb_driver.mod"], StringComparison.Ordinal);
        Assert.Contains("7000", files["machina_abb_driver.mod"], StringComparison.Ordinal);
        Assert.Contains("7001", files["machina_abb_monitor.mod"], StringComparison.Ordinal);
        Assert.DoesNotContain("{{", files["machina_abb_driver.mod"], StringComparison.Ordinal);
        Assert.DoesNotContain("{{", files["machina_abb_monitor.mod"], StringComparison.Ordinal);
    }

    [Theory]
    [InlineData(null, "7000", "HOSTNAME")]
    [InlineData("127.0.0.1", null, "PORT")]
    [InlineData("127.0.0.1", "seven", "whole number")]
    public void GetDeviceDriverModules_MissingOrBadParameter_ExplainsWhich(string? host, string? port, string expected)
    {
        var parameters = new Dictionary<string, string>();
        if (host is not null) { parameters["HOSTNAME"] = host; }
        if (port is not null) { parameters["PORT"] = port; }
        var ex = Assert.Throws<ArgumentException>(() => Robot.Create("Modules", "ABB").GetDeviceDriverModules(parameters));
        Assert.Contains(expected, ex.Message, StringComparison.Ordinal);
    }

    [Fact]
    public void GetDeviceDriverModules_Human_NotSupported() =>
        Assert.Throws<NotSupportedException>(() => Robot.Create("H", "HUMAN").GetDeviceDriverModules(new Dictionary<string, string>()));
}
