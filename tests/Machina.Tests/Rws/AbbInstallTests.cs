using System.Collections.Concurrent;
using Machina.Simulation.Rapid;
using Machina.Simulation.Rws;
using Machina.Tests.Online;
using Machina.Tests.Support;

namespace Machina.Tests.Rws;

/// <summary>
/// ConnectionManager("machina") on an ABB: Connect installs the driver through the RAPID twin's Robot Web Services (upload,
/// load into T_ROB1 and T_MACHINA_MONITOR, program pointer reset, start) and then streams to it; nothing is loaded by hand.
/// </summary>
public sealed class AbbInstallTests : IAsyncLifetime
{
    private const string Monitor = RwsTwinRig.MonitorTask;
    private readonly RwsTwinRig _rig = new(withMonitorTask: true);
    private readonly RapidTwinController _twin;
    private readonly RwsTwinServer _rws;
    private readonly int _port;

    public AbbInstallTests()
    {
        (_twin, _rws, _port) = (_rig.Twin, _rig.Rws, _rig.Port);
    }

    public Task InitializeAsync() => Task.CompletedTask;

    public async Task DisposeAsync() => await _rig.DisposeAsync();

    private Robot NewRobot(Action<Robot>? configure = null)
    {
        var bot = Robot.Create("HelloRobot", "ABB");
        bot.ControlMode("online");
        bot.ConnectTimeout = OnlineTestSupport.Limit;
        bot.WebServices = new RobotWebServicesOptions { Port = _rws.Port };
        configure?.Invoke(bot);
        return bot;
    }

    [Fact]
    public async Task ConnectionManagerMachina_ConnectInstallsAndStartsTheDriver_HelloRobotSevenOfSeven()
    {
        var executed = new ConcurrentQueue<int>();
        Robot bot = NewRobot(b => b.ActionExecuted += (_, e) => executed.Enqueue(e.LastAction.Id));
        Assert.True(bot.ConnectionManager("machina"));
        Assert.Empty(_twin.Task().Program.Modules);

        await bot.ConnectAsync("127.0.0.1", _port).WaitAsync(OnlineTestSupport.Limit);
        try
        {
            ReferencePrograms.HelloRobot(bot);
            await bot.WaitForCompletionAsync().WaitAsync(OnlineTestSupport.Limit);

            Assert.Equal([1, 2, 3, 4, 5, 6, 7], executed);
            Assert.Contains("Hello Robot!", _twin.Pendant.Lines);
            Assert.Equal(["Machina_Driver"], _twin.Task().Program.Modules.Select(m => m.Name));
            Assert.Equal(["Machina_Monitor"], _twin.Task(Monitor).Program.Modules.Select(m => m.Name));
            IReadOnlyDictionary<string, string> expected = AbbDriverModules.Create("127.0.0.1", _port);
            Assert.Equal(["$HOME/machina_abb_driver.mod", "$HOME/machina_abb_monitor.mod"], _rws.Files.Keys.Order(StringComparer.Ordinal));
            Assert.Equal(expected["machina_abb_driver.mod"], _rws.Files["$HOME/machina_abb_driver.mod"]);
            Assert.Equal(expected["machina_abb_monitor.mod"], _rws.Files["$HOME/machina_abb_monitor.mod"]);
            Assert.Contains((10002, "The program pointer of task T_ROB1 has been reset."), _rws.EventLog);
            Assert.Equal(RapidProgramState.Running, _twin.Task().State);
            Assert.Equal(["MoveL", "MoveL", "MoveL", "MoveAbsJ"],
                _twin.Arm.Trace.Where(t => t.Kind == Machina.Simulation.Twin.TwinTraceKind.Motion).Select(t => t.Text));
        }
        finally
        {
            await bot.DisconnectAsync();
        }
    }

    [Fact]
    public async Task ConnectionManagerMachina_Reconnect_LeavesTheRunningDriverAlone()
    {
        Robot bot = NewRobot();
        Assert.True(bot.ConnectionManager("machina"));
        await bot.ConnectAsync("127.0.0.1", _port).WaitAsync(OnlineTestSupport.Limit);
        await bot.DisconnectAsync();
        _rws.OperationMode = "MANR";   // a reinstall would be refused now: the second Connect must not try one

        await bot.ConnectAsync("127.0.0.1", _port).WaitAsync(OnlineTestSupport.Limit);
        try
        {
            bot.SpeedTo(100);
            bot.Move(0, 0, 10);
            await bot.WaitForCompletionAsync().WaitAsync(OnlineTestSupport.Limit);

            Assert.Single(_rws.EventLog, e => e.Code == 10002 && e.Title.Contains("T_ROB1", StringComparison.Ordinal));
            Assert.Equal(RapidProgramState.Running, _twin.Task().State);
            Assert.Equal(["MoveL"], _twin.Arm.Trace.Where(t => t.Kind == Machina.Simulation.Twin.TwinTraceKind.Motion).Select(t => t.Text));
        }
        finally
        {
            await bot.DisconnectAsync();
        }
    }

    [Fact]
    public async Task ConnectionManagerMachina_ManualMode_ConnectRefusedWithTheReason_NothingUploaded()
    {
        _rws.OperationMode = "MANR";
        Robot bot = NewRobot();
        Assert.True(bot.ConnectionManager(ConnectionType.Machina));

        var ex = await Assert.ThrowsAsync<RobotWebServicesException>(() => bot.ConnectAsync("127.0.0.1", _port).WaitAsync(OnlineTestSupport.Limit));

        Assert.Equal("Machina did not install its driver: the controller is in manual reduced-speed mode (MANR); Machina starts its driver " +
            "only in automatic mode (AUTO). Turn the mode switch to automatic and confirm it on the FlexPendant, then connect again.", ex.Message);
        Assert.Empty(_rws.Files);
        Assert.False(_twin.IsRunning);
        Assert.False(bot.IsConnected);
    }

    [Fact]
    public async Task InstallDriver_SpeedRatioAboveTheAllowedOne_Refused()
    {
        _rws.SpeedRatio = 80;
        Robot bot = NewRobot(b => b.WebServices = new RobotWebServicesOptions { Port = _rws.Port, MaxSpeedRatio = 25 });

        var ex = await Assert.ThrowsAsync<RobotWebServicesException>(() => bot.InstallDriverAsync("127.0.0.1", _port).WaitAsync(OnlineTestSupport.Limit));

        Assert.Equal("Machina did not install its driver: the speed ratio is 80 %, above the 25 % allowed by RobotWebServicesOptions.MaxSpeedRatio. " +
            "Lower it on the FlexPendant (or raise MaxSpeedRatio if this speed is intended), then connect again.", ex.Message);
        Assert.Empty(_rws.Files);
    }

    [Fact]
    public async Task InstallDriver_MastershipHeldByTheFlexPendant_RefusedWithTheHolder()
    {
        _rws.MastershipHeldBy = "FlexPendant";
        Robot bot = NewRobot();

        var ex = await Assert.ThrowsAsync<RobotWebServicesException>(() => bot.InstallDriverAsync("127.0.0.1", _port).WaitAsync(OnlineTestSupport.Limit));

        Assert.Equal("Could not get mastership of the controller: the controller answered HTTP 403: Mastership is held by FlexPendant.", ex.Message);
        Assert.Equal(403, ex.HttpStatus);
        Assert.Empty(_rws.Files);
    }

    [Fact]
    public void ConnectionManagerMachina_OnAUr_RefusedWithTheWarning()
    {
        var bot = Robot.Create("UR", "UR");
        var lines = new List<string>();
        using IDisposable sink = bot.Logger.AddSink(e => lines.Add(e.Message), LogLevel.WARNING);

        Assert.False(bot.ConnectionManager("machina"));

        Assert.Equal([Robot.MachinaManagerRefused], lines);
    }
}
