using Machina.Simulation.Rapid;
using Machina.Simulation.Rws;
using Machina.Tests.Support;

namespace Machina.Tests.Cli;

/// <summary><c>machina drivers abb --install</c> installs and starts the driver through the twin's Robot Web Services.</summary>
public sealed class DriversInstallCliTests : IAsyncLifetime
{
    private readonly RwsTwinRig _rig = new(withMonitorTask: false);
    private readonly RapidTwinController _twin;
    private readonly RwsTwinServer _rws;
    private readonly int _port;

    public DriversInstallCliTests()
    {
        (_twin, _rws, _port) = (_rig.Twin, _rig.Rws, _rig.Port);
    }

    public Task InitializeAsync() => Task.CompletedTask;

    public async Task DisposeAsync() => await _rig.DisposeAsync();

    [Fact]
    public async Task DriversAbbInstall_LoadsAndStartsTheDriver_AndSaysHowToConnect()
    {
        using var cli = new CliRunner();
        string port = _port.ToString(System.Globalization.CultureInfo.InvariantCulture);

        CliResult result = await cli.RunAsync("drivers", "abb", "--install", "--host", "127.0.0.1", "--port", port,
            "--rws-port", _rws.Port.ToString(System.Globalization.CultureInfo.InvariantCulture));

        Assert.Equal(0, result.Exit);
        Assert.EndsWith($"The driver runs on the controller and listens on 127.0.0.1:{port}. Then: machina run PROGRAM --brand abb --host 127.0.0.1 --port {port}",
            result.Stderr.TrimEnd(), StringComparison.Ordinal);
        Assert.Contains("Loaded $HOME/machina_abb_driver.mod into T_ROB1.", result.Stderr, StringComparison.Ordinal);
        Assert.True(_twin.IsRunning);
        Assert.Equal(["Machina_Driver"], _twin.Task().Program.Modules.Select(m => m.Name));
    }

    [Fact]
    public async Task DriversAbbInstall_ManualMode_FailsWithTheReason()
    {
        _rws.OperationMode = "MANF";
        using var cli = new CliRunner();

        CliResult result = await cli.RunAsync("drivers", "abb", "--install", "--host", "127.0.0.1",
            "--rws-port", _rws.Port.ToString(System.Globalization.CultureInfo.InvariantCulture));

        Assert.NotEqual(0, result.Exit);
        Assert.Contains("Machina did not install its driver: the controller is in manual full-speed mode (MANF);", result.Stderr, StringComparison.Ordinal);
        Assert.False(_twin.IsRunning);
    }

    [Fact]
    public async Task DriversKukaInstall_IsAUsageError()
    {
        using var cli = new CliRunner();

        CliResult result = await cli.RunAsync("drivers", "kuka", "--install", "--host", "127.0.0.1");

        Assert.Equal(2, result.Exit);
        Assert.Contains("machina drivers --install works on ABB controllers only (through Robot Web Services), not KUKA.", result.Stderr, StringComparison.Ordinal);
    }
}
