using Machina.Simulation.Rapid;
using Machina.Simulation.Rws;
using Machina.Tests.Support;

namespace Machina.Tests.Rws;

/// <summary>
/// The RAPID twin's Robot Web Services against hostile clients (issue 40): a digest header seen on the wire works only once and
/// only for its own request, nonces expire, a slow request is answered 408, a number out of range is a 400 (the connection
/// kept), and the file service keeps its keys inside their folder.
/// </summary>
public sealed class RwsTwinLimitsTests : IAsyncLifetime
{
    private const string OpMode = "/rw/panel/opmode";
    private readonly ManualClock _clock = new();
    private readonly RapidTwinController _twin = new(new RapidTwinOptions());
    private readonly RwsTwinServer _rws;

    public RwsTwinLimitsTests()
    {
        _twin.Task();
        _rws = new RwsTwinServer(_twin, time: _clock);
        _rws.Start();
    }

    public Task InitializeAsync() => Task.CompletedTask;

    public async Task DisposeAsync()
    {
        await _rws.DisposeAsync();
        Assert.True(_twin.StopTasks(TimeSpan.FromSeconds(10)), "the RAPID tasks to stop");
    }

    [Fact]
    public async Task DigestHeader_SentAgain_IsRefused_TheCountMustGrow()
    {
        string nonce = (await Get(OpMode, null)).Nonce;
        string header = RawHttp.Digest(nonce, "GET", OpMode, "00000001");
        Assert.Equal(200, (await Get(OpMode, header)).Status);

        // The same header again (a replay from the wire, no cookie): refused with a new challenge.
        RawAnswer replay = await Get(OpMode, header);
        Assert.Equal(401, replay.Status);
        Assert.NotEqual(nonce, replay.Nonce);

        // The same nonce counted up is the client's next request: taken.
        Assert.Equal(200, (await Get(OpMode, RawHttp.Digest(nonce, "GET", OpMode, "00000002"))).Status);
    }

    [Fact]
    public async Task DigestHeader_ForAnotherPath_IsRefused()
    {
        string nonce = (await Get(OpMode, null)).Nonce;
        string header = RawHttp.Digest(nonce, "GET", OpMode, "00000001");

        RawAnswer elsewhere = await Get("/rw/panel/speedratio", header);

        Assert.Equal(401, elsewhere.Status);
        // The nonce was not used up by the refusal: the header on its own path is still taken.
        Assert.Equal(200, (await Get(OpMode, header)).Status);
    }

    [Fact]
    public async Task Nonce_AfterItsLifetime_IsStale_TheNextChallengeSaysSo()
    {
        _rws.NonceLifetime = TimeSpan.FromMinutes(1);
        string nonce = (await Get(OpMode, null)).Nonce;
        _clock.Advance(TimeSpan.FromSeconds(61));

        RawAnswer late = await Get(OpMode, RawHttp.Digest(nonce, "GET", OpMode, "00000001"));

        Assert.Equal(401, late.Status);
        Assert.Contains("stale=TRUE", late.Header("WWW-Authenticate"), StringComparison.Ordinal);
        Assert.Equal(200, (await Get(OpMode, RawHttp.Digest(late.Nonce, "GET", OpMode, "00000001"))).Status);
    }

    [Fact]
    public async Task SlowRequestHead_AnsweredRequestTimeout_AndClosed()
    {
        _rws.RequestDeadline = TimeSpan.FromMilliseconds(200);
        using RawHttp http = await RawHttp.ConnectAsync(_rws.Port);
        await http.SendAsync("GET /rw/panel/opmode HTTP/1.1\r\nHost: x\r\n"); // and never the blank line

        RawAnswer answer = await http.ReadAnswerAsync();

        Assert.Equal(408, answer.Status);
        Assert.Equal("close", answer.Header("Connection"));
        Assert.True(await http.ClosedAsync(), "the server to close the connection after its 408");
    }

    [Fact]
    public async Task RequestHeadPastItsCap_Answered431()
    {
        RawAnswer answer = await RawHttp.RequestAsync(_rws.Port, "GET / HTTP/1.1\r\nX-Long: " + new string('a', RwsHttp.MaxHead) + "\r\n\r\n");

        Assert.Equal(431, answer.Status);
    }

    [Fact]
    public async Task SpeedRatioTooLargeForANumber_Refused400WithTheReason_ConnectionKept()
    {
        using RawHttp http = await RawHttp.ConnectAsync(_rws.Port);
        string cookie = await LogInAsync(http);
        const string form = "speed-ratio=99999999999";
        await http.SendAsync($"POST /rw/panel/speedratio?action=setspeedratio HTTP/1.1\r\nHost: x\r\nCookie: {cookie}\r\n" +
            $"Content-Type: application/x-www-form-urlencoded\r\nContent-Length: {form.Length}\r\n\r\n{form}");

        RawAnswer refused = await http.ReadAnswerAsync();

        Assert.Equal(400, refused.Status);
        Assert.Contains("The speed ratio must be a whole number between 0 and 100, not 99999999999.", refused.Body, StringComparison.Ordinal);
        Assert.Equal(100, _rws.SpeedRatio);
        await http.SendAsync($"GET /rw/panel/speedratio HTTP/1.1\r\nHost: x\r\nCookie: {cookie}\r\n\r\n");
        Assert.Equal(200, (await http.ReadAnswerAsync()).Status);
    }

    [Theory]
    [InlineData("/fileservice/$HOME/../../etc/machina.mod")]
    [InlineData("/fileservice/$HOME/%2e%2e/machina.mod")]
    [InlineData("/fileservice/$HOME//machina.mod")]
    [InlineData("/fileservice/$HOME/..%5Cmachina.mod")]
    public async Task FileKeyLeavingItsFolder_Refused400_NothingStored(string target)
    {
        using RawHttp http = await RawHttp.ConnectAsync(_rws.Port);
        string cookie = await LogInAsync(http);
        await http.SendAsync($"PUT {target} HTTP/1.1\r\nHost: x\r\nCookie: {cookie}\r\nContent-Length: 3\r\n\r\nabc");

        RawAnswer refused = await http.ReadAnswerAsync();

        Assert.Equal(400, refused.Status);
        Assert.Contains("is not a path under a controller folder", refused.Body, StringComparison.Ordinal);
        Assert.Empty(_rws.Files);
    }

    [Fact]
    public async Task Sessions_PastTheirCap_TheOldestEnds_TheNewestHolds()
    {
        using RawHttp first = await RawHttp.ConnectAsync(_rws.Port);
        string oldest = await LogInAsync(first);
        string newest = oldest;
        for (int i = 0; i < RwsTwinServer.MaxSessions; i++)
        {
            newest = await LogInAsync(first);
        }

        Assert.Equal(401, (await Get(OpMode, null, oldest)).Status);
        Assert.Equal(200, (await Get(OpMode, null, newest)).Status);
    }

    private async Task<RawAnswer> Get(string path, string? authorization, string? cookie = null) =>
        await RawHttp.RequestAsync(_rws.Port, $"GET {path} HTTP/1.1\r\nHost: x\r\n" + (authorization is null ? "" : $"Authorization: {authorization}\r\n")
            + (cookie is null ? "" : $"Cookie: {cookie}\r\n") + "\r\n");

    /// <summary>Authenticates on <paramref name="http"/>'s connection; returns the session cookie.</summary>
    private static async Task<string> LogInAsync(RawHttp http)
    {
        await http.SendAsync($"GET {OpMode} HTTP/1.1\r\nHost: x\r\n\r\n");
        string nonce = (await http.ReadAnswerAsync()).Nonce;
        await http.SendAsync($"GET {OpMode} HTTP/1.1\r\nHost: x\r\nAuthorization: {RawHttp.Digest(nonce, "GET", OpMode, "00000001")}\r\n\r\n");
        RawAnswer answer = await http.ReadAnswerAsync();
        Assert.Equal(200, answer.Status);
        return answer.Header("Set-Cookie").Split(';')[0];
    }
}
