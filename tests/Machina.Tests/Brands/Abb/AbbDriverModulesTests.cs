namespace Machina.Tests.Brands.Abb;

public class AbbDriverModulesTests
{
    [Fact]
    public void Create_HostAndPort_FillsDriverAndMonitorPlaceholders()
    {
        var files = AbbDriverModules.Create("192.168.125.1", 7000);
        Assert.Equal(["machina_abb_driver.mod", "machina_abb_driver.pgf", "machina_abb_monitor.mod", "machina_abb_monitor.pgf"], files.Keys.Order());
        string driver = files["machina_abb_driver.mod"];
        string monitor = files["machina_abb_monitor.mod"];
        Assert.Contains("PERS string SERVER_IP := \"192.168.125.1\";", driver, StringComparison.Ordinal);
        Assert.Contains("CONST num SERVER_PORT := 7000;", driver, StringComparison.Ordinal);
        Assert.Contains("CONST num MONITOR_PORT := 7001;", monitor, StringComparison.Ordinal);
        Assert.Contains("PERS num monitorUpdateInterval := 0.02;", monitor, StringComparison.Ordinal);
        Assert.DoesNotContain("{{", driver + monitor, StringComparison.Ordinal);
        Assert.StartsWith("MODULE Machina_Driver", driver, StringComparison.Ordinal);
        Assert.Contains("<Module>machina_abb_monitor.mod</Module>", files["machina_abb_monitor.pgf"], StringComparison.Ordinal);
    }

    [Fact]
    public void Create_MonitorRate_SetsIntervalInSeconds() =>
        Assert.Contains("monitorUpdateInterval := 0.1;", AbbDriverModules.Create("127.0.0.1", 7000, 10)["machina_abb_driver.mod"], StringComparison.Ordinal);

    [Fact]
    public void Create_BadArguments_Throw()
    {
        Assert.Throws<ArgumentOutOfRangeException>(() => AbbDriverModules.Create("127.0.0.1", 65535));
        Assert.Throws<ArgumentException>(() => AbbDriverModules.Create("bad\"host", 7000));
        Assert.Throws<ArgumentOutOfRangeException>(() => AbbDriverModules.Create("127.0.0.1", 7000, 0));
    }

    [Fact]
    public void DriverModule_VersionAndProgress_MatchWhatTheHostExpects()
    {
        string driver = AbbDriverModules.Create("127.0.0.1", 7000)["machina_abb_driver.mod"];
        var version = AbbMessageFormat.DriverVersion;
        Assert.Contains($"CONST string DRIVER_VERSION_MAJOR := \"{version.Major}\";", driver, StringComparison.Ordinal);
        Assert.Contains($"CONST string DRIVER_VERSION_MINOR := \"{version.Minor}\";", driver, StringComparison.Ordinal);
        Assert.Contains($"CONST string DRIVER_VERSION_PATCH := \"{version.Patch}\";", driver, StringComparison.Ordinal);
        Assert.True(version.ReportsProgress);
        Assert.Contains("SocketSend clientSocket \\Str:=\"$25 \" + NumToStr(lastExecutedId, 0) + \" \" + NumToStr(lastReceivedId, 0) + \";\";", driver, StringComparison.Ordinal);
        Assert.Contains("lastExecutedId := r.id;", driver, StringComparison.Ordinal);
        Assert.Contains("lastReceivedId := request.id;", driver, StringComparison.Ordinal);
    }

    [Fact]
    public void DriverModule_EveryInstructionCode_HasACase()
    {
        string driver = AbbDriverModules.Create("127.0.0.1", 7000)["machina_abb_driver.mod"];
        foreach (int code in Enum.GetValues<AbbInstructionCode>().Cast<int>().Where(c => c != 102))
        {
            Assert.Contains($"CASE {code}:", driver, StringComparison.Ordinal);
        }
    }
}
