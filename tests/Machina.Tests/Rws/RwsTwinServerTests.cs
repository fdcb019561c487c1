using Machina.Simulation.Rapid;
using Machina.Simulation.Rws;
using Machina.Tests.Online;

namespace Machina.Tests.Rws;

/// <summary>The RWS client against the RAPID twin's Robot Web Services: what each resource does to the running twin.</summary>
public sealed class RwsTwinServerTests : IAsyncLifetime
{
    private const string Probe = """
        MODULE RwsProbe
          VAR num wanted := 0;
          VAR num seen := 0;
          PROC main()
            WHILE wanted = 0 DO
              WaitTime 0.01;
            ENDWHILE
            SetDO doFlag, 1;
            WaitDI diGo, 1;
            seen := wanted * 2;
            ! The client starts RAPID continuously (cycle=forever): without EXIT, main would start again.
            EXIT;
          ENDPROC
        ENDMODULE
        """;

    private readonly RapidTwinController _twin = new(new RapidTwinOptions
    {
        RealTime = true,
        Signals = [("doFlag", "signaldo"), ("diGo", "signaldi")],
    });

    private readonly RwsTwinServer _rws;
    private readonly RwsClient _client;

    public RwsTwinServerTests()
    {
        _twin.Task();
        _rws = new RwsTwinServer(_twin);
        _rws.Start();
        _client = new RwsClient("127.0.0.1", new RobotWebServicesOptions { Port = _rws.Port, Timeout = OnlineTestSupport.Limit });
    }

    public Task InitializeAsync() => Task.CompletedTask;

    public async Task DisposeAsync()
    {
        _client.Dispose();
        await _rws.DisposeAsync();
        Assert.True(_twin.StopTasks(TimeSpan.FromSeconds(10)), "the RAPID tasks to stop");
    }

    [Fact]
    public async Task VariableAndSignalWrittenThroughRws_AreWhatTheRunningModuleSees()
    {
        await _client.RequestMastershipAsync();
        await _client.UploadFileAsync("$HOME/probe.mod", Probe);
        await _client.LoadModuleAsync("T_ROB1", "$HOME/probe.mod");
        await _client.ResetProgramPointerAsync();
        await _client.StartAsync();
        Assert.Equal("running", await _client.GetExecutionStateAsync());
        Assert.Equal(0, await _client.GetSignalAsync("doFlag"));

        await _client.SetSymbolAsync("T_ROB1", "RwsProbe", "wanted", "21");
        await UntilAsync(async () => await _client.GetSignalAsync("doFlag") == 1, "the module to see wanted and set doFlag");
        Assert.Equal("0", await _client.GetSymbolAsync("T_ROB1", "RwsProbe", "seen"));

        await _client.SetSignalAsync("Local/DRV_1/diGo", 1);
        await UntilAsync(async () => await _client.GetSymbolAsync("T_ROB1", "RwsProbe", "seen") == "42", "the module to see diGo and compute seen");
        await UntilAsync(async () => await _client.GetExecutionStateAsync() == "stopped", "main to end");
        Assert.Equal(RapidProgramState.Finished, _twin.Task().State);
        Assert.Equal("21", await _client.GetSymbolAsync("T_ROB1", "RwsProbe", "wanted"));
    }

    [Fact]
    public async Task ModuleWithASyntaxError_LoadRefusedWithTheControllersMessageAndLine()
    {
        await _client.RequestMastershipAsync();
        await _client.UploadFileAsync("$HOME/bad.mod", "MODULE Bad\n  PROC main()\n    TPWrite \"a\";\n    x := ;\n  ENDPROC\nENDMODULE\n");

        var ex = await Assert.ThrowsAsync<RobotWebServicesException>(() => _client.LoadModuleAsync("T_ROB1", "$HOME/bad.mod"));

        Assert.Equal("Could not load $HOME/bad.mod into the task T_ROB1: the controller answered HTTP 400: " +
            "bad.mod: Load error: line 4: Syntax error: an expression expected, found ';'", ex.Message);
        Assert.Equal(400, ex.HttpStatus);
        Assert.Contains((0, "bad.mod: Load error: line 4: Syntax error: an expression expected, found ';'"), await _client.GetEventLogAsync());
        Assert.Empty(_twin.Task().Program.Modules);
    }

    [Fact]
    public async Task StartInManualMode_RefusedWithTheReason_NothingRuns()
    {
        await _client.RequestMastershipAsync();
        await _client.UploadFileAsync("$HOME/probe.mod", Probe);
        await _client.LoadModuleAsync("T_ROB1", "$HOME/probe.mod");
        _rws.OperationMode = "MANR";

        var ex = await Assert.ThrowsAsync<RobotWebServicesException>(() => _client.StartAsync());

        Assert.Equal("Could not start RAPID execution: the controller answered HTTP 400: Start refused: the controller is in manual mode (MANR); " +
            "a remote client can start RAPID only in automatic mode.", ex.Message);
        Assert.Equal("MANR", await _client.GetOperationModeAsync());
        Assert.Equal("stopped", await _client.GetExecutionStateAsync());
        Assert.Equal(RapidProgramState.Ready, _twin.Task().State);
    }

    [Fact]
    public async Task LoadingAModuleOfTheSameName_ReplacesIt_TheNewOneRuns()
    {
        await _client.RequestMastershipAsync();
        await _client.UploadFileAsync("$HOME/probe.mod", Probe);
        await _client.LoadModuleAsync("T_ROB1", "$HOME/probe.mod");
        await _client.UploadFileAsync("$HOME/probe.mod", "MODULE RwsProbe\n  VAR num seen := 7;\n  PROC main()\n    seen := 8;\n    EXIT;\n  ENDPROC\nENDMODULE\n");
        await _client.LoadModuleAsync("T_ROB1", "$HOME/probe.mod");
        await _client.StartAsync();

        await UntilAsync(async () => await _client.GetExecutionStateAsync() == "stopped", "main to end");
        Assert.Equal("8", await _client.GetSymbolAsync("T_ROB1", "RwsProbe", "seen"));
        Assert.Equal(["RwsProbe"], _twin.Task().Program.Modules.Select(m => m.Name));
    }

    [Fact]
    public async Task VariableWithoutMastership_RefusedWithTheDocumentedCode()
    {
        await _client.RequestMastershipAsync();
        await _client.UploadFileAsync("$HOME/probe.mod", Probe);
        await _client.LoadModuleAsync("T_ROB1", "$HOME/probe.mod");
        await _client.ReleaseMastershipAsync();

        var ex = await Assert.ThrowsAsync<RobotWebServicesException>(() => _client.SetSymbolAsync("T_ROB1", "RwsProbe", "wanted", "3"));

        Assert.Equal(RwsTwinServer.MastershipRequiredCode, ex.ControllerCode);
        Assert.Equal("Could not set T_ROB1/RwsProbe/wanted to 3: the controller answered HTTP 400, code -1073414146: Updating RAPID data needs RAPID mastership.", ex.Message);
        Assert.Equal("0", await _client.GetSymbolAsync("T_ROB1", "RwsProbe", "wanted"));
    }

    [Fact]
    public async Task WrongPassword_RefusedWith401_AndTheAdvice()
    {
        using var client = new RwsClient("127.0.0.1", new RobotWebServicesOptions { Port = _rws.Port, Password = "wrong", Timeout = OnlineTestSupport.Limit });

        var ex = await Assert.ThrowsAsync<RobotWebServicesException>(() => client.GetOperationModeAsync());

        Assert.Equal(401, ex.HttpStatus);
        Assert.StartsWith("Could not read the operating mode: the controller refused the user name or password (HTTP 401).", ex.Message, StringComparison.Ordinal);
    }

    [Fact]
    public async Task PanelAndMotion_ReportTheTwin()
    {
        Assert.Equal("AUTO", await _client.GetOperationModeAsync());
        Assert.Equal("motoron", await _client.GetControllerStateAsync());
        await _client.SetSpeedRatioAsync(40);
        Assert.Equal(40, await _client.GetSpeedRatioAsync());
        Assert.Equal(40, _rws.SpeedRatio);
        Joints j = await _client.GetJointTargetAsync();
        Assert.Equal(new[] { 0.0, 0, 0, 0, 90, 0 }, new[] { j.J1, j.J2, j.J3, j.J4, j.J5, j.J6 });
        (Vector position, double[] q) = await _client.GetRobTargetAsync();
        Pose tcp = _twin.Arm.Tcp;
        Assert.True(position.IsSimilar(tcp.Position, 1e-9), position.ToString());
        Assert.Equal(tcp.Rotation.W, q[0], 9);
        Assert.Equal(["T_ROB1"], await _client.GetTasksAsync());
    }

    private static async Task UntilAsync(Func<Task<bool>> condition, string what)
    {
        long start = TimeProvider.System.GetTimestamp();
        while (!await condition())
        {
            Assert.True(TimeProvider.System.GetElapsedTime(start) < OnlineTestSupport.Limit, $"Timed out waiting for {what}.");
            await Task.Delay(10);
        }
    }
}
