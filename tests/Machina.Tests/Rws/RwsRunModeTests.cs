using System.Net;
using Machina.Simulation.Rapid;
using Machina.Simulation.Rws;

namespace Machina.Tests.Rws;

/// <summary>
/// RWS's start takes the run mode (<c>cycle=forever|once|asis</c>) and <c>setcycle</c> sets it, as the RWS manual's "Start RAPID
/// Execution" and "Set number of execution cycles" describe; the execution state shows it; the tasks list their type.
/// </summary>
public sealed class RwsRunModeTests : IAsyncLifetime
{
    private static readonly TimeSpan Limit = TimeSpan.FromSeconds(20);

    private readonly RapidTwinController _twin = new();
    private readonly RwsTwinServer _rws;
    private readonly HttpClient _http;

    public RwsRunModeTests()
    {
        _twin.Load(("T.mod", Simulation.Rapid.RapidRunModeTests.ThreeCycles));
        _rws = new RwsTwinServer(_twin);
        _rws.Start();
        _http = RwsTestClient.For(_rws.Port, new CookieContainer(), Limit);
    }

    public Task InitializeAsync() => Task.CompletedTask;

    public async Task DisposeAsync()
    {
        _http.Dispose();
        await _rws.DisposeAsync();
        Assert.True(_twin.StopTasks(TimeSpan.FromSeconds(10)), "the RAPID tasks to stop");
    }

    [Theory]
    [InlineData("forever", new[] { "cycle 1", "cycle 2", "cycle 3" })]
    [InlineData("once", new[] { "cycle 1" })]
    public async Task Start_RunsMainAsTheCycleFieldSays_AndTheExecutionStateShowsIt(string cycle, string[] lines)
    {
        Assert.Equal(HttpStatusCode.NoContent, (await StartAsync(cycle)).StatusCode);

        Assert.True(SpinWait.SpinUntil(() => _twin.Task().State == RapidProgramState.Finished, Limit), "main to end");
        Assert.Equal(lines, _twin.Pendant.Lines);
        string state = await _http.GetStringAsync("/rw/rapid/execution");
        Assert.Contains($"<span class=\"cycle\">{cycle}</span>", state, StringComparison.Ordinal);
    }

    [Fact]
    public async Task SetCycle_WithMastership_IsWhatAStartAsIsRuns()
    {
        using HttpResponseMessage refused = await PostAsync("/rw/rapid/execution?action=setcycle", "cycle=forever");
        Assert.Equal(HttpStatusCode.BadRequest, refused.StatusCode);
        Assert.Equal(RapidExecutionCycle.Once, _twin.Cycle);

        using HttpResponseMessage master = await PostAsync("/rw/mastership?action=request", "");
        using HttpResponseMessage set = await PostAsync("/rw/rapid/execution?action=setcycle", "cycle=forever");
        Assert.Equal(HttpStatusCode.NoContent, set.StatusCode);
        Assert.Equal(HttpStatusCode.NoContent, (await StartAsync("asis")).StatusCode);

        Assert.True(SpinWait.SpinUntil(() => _twin.Task().State == RapidProgramState.Finished, Limit), "main to end");
        Assert.Equal(["cycle 1", "cycle 2", "cycle 3"], _twin.Pendant.Lines);
    }

    [Fact]
    public async Task Start_WithAnUnknownCycle_IsRefused_NothingRuns()
    {
        using HttpResponseMessage response = await StartAsync("twice");

        Assert.Equal(HttpStatusCode.BadRequest, response.StatusCode);
        Assert.Contains("The cycle must be forever, once or asis, not \"twice\".", await response.Content.ReadAsStringAsync(), StringComparison.Ordinal);
        Assert.Equal(RapidProgramState.Ready, _twin.Task().State);
    }

    [Fact]
    public async Task Tasks_ListTheirTypeAndWhetherTheyMove()
    {
        _twin.Task("T_BG").Type = RapidTaskType.SemiStatic;

        string tasks = await _http.GetStringAsync("/rw/rapid/tasks");

        Assert.Contains("<span class=\"tasktype\">Normal</span>", tasks, StringComparison.Ordinal);
        Assert.Contains("<span class=\"motiontask\">TRUE</span>", tasks, StringComparison.Ordinal);
        Assert.Contains("<span class=\"motiontask\">FALSE</span>", tasks, StringComparison.Ordinal);
        Assert.Contains("<span class=\"tasktype\">SemiStatic</span>", tasks, StringComparison.Ordinal);
    }

    private Task<HttpResponseMessage> StartAsync(string cycle) => PostAsync("/rw/rapid/execution?action=start",
        $"regain=continue&execmode=continue&cycle={cycle}&condition=none&stopatbp=disabled&alltaskbytsp=false");

    private Task<HttpResponseMessage> PostAsync(string path, string form) =>
        _http.PostAsync(path, new StringContent(form, System.Text.Encoding.ASCII, "application/x-www-form-urlencoded"));
}
