using System.Net;
using System.Net.WebSockets;
using System.Text;
using System.Xml.Linq;
using Machina.Simulation.Rapid;
using Machina.Simulation.Rws;

namespace Machina.Tests.Rws;

/// <summary>
/// RWS 1.0 subscriptions on the twin's Robot Web Services, with .NET's own HTTP (digest log-on) and WebSocket clients as a
/// third-party client would use them: an event arrives when a subscribed signal or panel state changes, and none for the others.
/// </summary>
public sealed class RwsSubscriptionTests : IAsyncLifetime
{
    private static readonly TimeSpan Limit = TimeSpan.FromSeconds(20);
    private readonly RapidTwinController _twin = new(new RapidTwinOptions { Signals = [("DO_1", "signaldo"), ("DO_2", "signaldo")] });
    private readonly RwsTwinServer _rws;
    private readonly CookieContainer _cookies = new();
    private readonly HttpClient _http;

    public RwsSubscriptionTests()
    {
        _rws = new RwsTwinServer(_twin);
        _rws.Start();
        _http = RwsTestClient.For(_rws.Port, _cookies, Limit);
    }

    public Task InitializeAsync() => Task.CompletedTask;

    public async Task DisposeAsync()
    {
        _http.Dispose();
        await _rws.DisposeAsync();
    }

    private Task<HttpResponseMessage> Subscribe(params string[] resources) => _http.PostAsync("/subscription", new FormUrlEncodedContent(
        resources.SelectMany((r, i) => new KeyValuePair<string, string>[] { new("resources", $"{i + 1}"), new($"{i + 1}", r), new($"{i + 1}-p", "1") })));

    private static async Task<XElement[]> NextEvent(ClientWebSocket socket, CancellationToken cancellation)
    {
        var buffer = new byte[64 * 1024];
        WebSocketReceiveResult result = await socket.ReceiveAsync(buffer, cancellation);
        Assert.Equal(WebSocketMessageType.Text, result.MessageType);
        Assert.True(result.EndOfMessage);
        XNamespace x = "http://www.w3.org/1999/xhtml";
        return [.. XDocument.Parse(Encoding.UTF8.GetString(buffer, 0, result.Count)).Descendants(x + "li")];
    }

    private static string Span(XElement item, string cls) =>
        item.Elements().Single(e => e.Name.LocalName == "span" && (string?)e.Attribute("class") == cls).Value;

    [Fact]
    public async Task ASubscribedSignalAndTheOperatingMode_SendAnEventEachTimeTheyChange()
    {
        using var cancellation = new CancellationTokenSource(Limit);
        using HttpResponseMessage created = await Subscribe("/rw/iosystem/signals/DO_1;state", "/rw/panel/opmode");
        Assert.Equal(HttpStatusCode.Created, created.StatusCode);
        Uri poll = created.Headers.Location!;
        Assert.Equal($"ws://127.0.0.1:{_rws.Port}/poll/1", poll.ToString());
        using var socket = new ClientWebSocket();
        socket.Options.Cookies = _cookies;
        socket.Options.AddSubProtocol("robapi2_subscription");
        await socket.ConnectAsync(poll, cancellation.Token);
        Assert.Equal("robapi2_subscription", socket.SubProtocol);

        Assert.True(_twin.SetSignal("DO_2", 1)); // not subscribed: no event
        Assert.True(_twin.SetSignal("DO_1", 1));
        XElement[] first = await NextEvent(socket, cancellation.Token);
        XElement signal = Assert.Single(first);
        Assert.Equal("ios-signalstate-ev", (string?)signal.Attribute("class"));
        Assert.Equal("DO_1", (string?)signal.Attribute("title"));
        Assert.Equal("1", Span(signal, "lvalue"));
        Assert.Equal("/rw/iosystem/signals/DO_1;state", (string?)signal.Elements().First().Attribute("href"));

        _rws.OperationMode = "MANR";
        XElement mode = Assert.Single(await NextEvent(socket, cancellation.Token));
        Assert.Equal("pnl-opmode-ev", (string?)mode.Attribute("class"));
        Assert.Equal("MANR", Span(mode, "opmode"));

        // Deleted, the subscription closes its WebSocket.
        using HttpResponseMessage deleted = await _http.DeleteAsync("/subscription/1", cancellation.Token);
        Assert.Equal(HttpStatusCode.OK, deleted.StatusCode);
        WebSocketReceiveResult end = await socket.ReceiveAsync(new byte[256], cancellation.Token);
        Assert.Equal(WebSocketMessageType.Close, end.MessageType);
    }

    [Fact]
    public async Task AResourceWithoutEvents_IsRefused_AndAnUnknownPollIsNotFound()
    {
        using HttpResponseMessage refused = await Subscribe("/rw/rapid/tasks");
        Assert.Equal(HttpStatusCode.BadRequest, refused.StatusCode);
        Assert.Contains("serves no events of /rw/rapid/tasks", await refused.Content.ReadAsStringAsync(), StringComparison.Ordinal);

        using HttpResponseMessage logOn = await _http.GetAsync("/rw/panel/opmode"); // the session cookie
        using var socket = new ClientWebSocket();
        socket.Options.Cookies = _cookies;
        socket.Options.AddSubProtocol("robapi2_subscription");
        await Assert.ThrowsAsync<WebSocketException>(() => socket.ConnectAsync(new Uri($"ws://127.0.0.1:{_rws.Port}/poll/7"), CancellationToken.None));
    }
}
