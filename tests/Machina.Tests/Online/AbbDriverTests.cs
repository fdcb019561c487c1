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
