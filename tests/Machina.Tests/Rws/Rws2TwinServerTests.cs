using Machina.Simulation.Rapid;
using Machina.Simulation.Rws;
using Machina.Tests.Online;

namespace Machina.Tests.Rws;

/// <summary>RWS 2.0 as a client sees it on the twin: basic authentication and the v=2.0 media types.</summary>
public sealed class Rws2TwinServerTests : IAsyncLifetime
{
    private readonly RapidTwinController _twin = new();
    private readonly RwsTwinServer _rws;

    public Rws2TwinServerTests()
    {
        _twin.Task();
        _rws = new RwsTwinServer(_twin, rws2: true);
        _rws.Start();
    }

    public Task InitializeAsync() => Task.CompletedTask;

    public async Task DisposeAsync() => await _rws.DisposeAsync();

    [Fact]
    public async Task Rws2Client_BasicAuthenticationAndV2Media_ReadsAndSets()
    {
        using var client = new RwsClient("127.0.0.1", new RobotWebServicesOptions { Port = _rws.Port, UseRws2 = true, Rws2OverHttp = true, Timeout = OnlineTestSupport.Limit });

        Assert.Equal("AUTO", await client.GetOperationModeAsync());
        await client.SetSpeedRatioAsync(30);

        Assert.Equal(30, await client.GetSpeedRatioAsync());
        Assert.Equal(30, _rws.SpeedRatio);
    }

    [Fact]
    public async Task Rws1Client_OnAnRws2Controller_RefusedWith401()
    {
        using var client = new RwsClient("127.0.0.1", new RobotWebServicesOptions { Port = _rws.Port, Timeout = OnlineTestSupport.Limit });

        var ex = await Assert.ThrowsAsync<RobotWebServicesException>(() => client.GetOperationModeAsync());

        Assert.Equal(401, ex.HttpStatus);
    }

    [Fact]
    public async Task Rws2Client_WrongPassword_RefusedWith401()
    {
        using var client = new RwsClient("127.0.0.1", new RobotWebServicesOptions { Port = _rws.Port, UseRws2 = true, Rws2OverHttp = true, Password = "x", Timeout = OnlineTestSupport.Limit });

        var ex = await Assert.ThrowsAsync<RobotWebServicesException>(() => client.GetControllerStateAsync());

        Assert.Equal(401, ex.HttpStatus);
        Assert.StartsWith("Could not read the controller state: the controller refused the user name or password (HTTP 401).", ex.Message, StringComparison.Ordinal);
    }
}
