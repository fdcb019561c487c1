using System.Net;
using Machina.Simulation;
using Machina.Simulation.Rapid;
using Machina.Simulation.Rws;

namespace Machina.Tests.Cli;

/// <summary><c>machina drivers abb --install</c> installs and starts the driver through the twin's Robot Web Services.</summary>
public sealed class DriversInstallCliTests : IAsyncLifetime
{
    private readonly RapidTwinController _twin = new(new RapidTwinOptions { Model = RobotModels.Get("IRB 1600-8/1.45") });
    private readonly RwsTwinServer _rws;
    private readonly int _port;

    public DriversInstallCliTests()
    {
        (System.Net.Sockets.TcpListener driver, System.Net.Sockets.TcpListener monitor) = LoopbackPorts.BindPair();
        _port = ((IPEndPoint)driver.LocalEndpoint).Port;
        _twin.Task();
        _twin.Reserve(driver);
        _twin.Reserve(monitor);
        _rws = new RwsTwinServer(_twin);
        _rws.Start();
    }

    public Task InitializeAsync() => Task.CompletedTask;

    public async Task DisposeAsync()
    {
        await _rws.DisposeAsync();
        Assert.True(_twin.StopTasks(TimeSpan.FromSeconds(10)), "the RAPID tasks to stop");
    }

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
