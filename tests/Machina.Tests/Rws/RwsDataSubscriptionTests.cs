using System.Net;
using System.Net.WebSockets;
using System.Text;
using System.Xml.Linq;
using Machina.Simulation.Rapid;
using Machina.Simulation.Rws;

namespace Machina.Tests.Rws;

/// <summary>
/// RWS subscriptions to a RAPID persistent variable and to the event log, as the RWS manual describes them ("Subscribe on RAPID
/// persistent variable": a <c>rap-value-ev</c> with the <c>rap-data</c> value; "Subscribe on elog domain": one
/// <c>elog-message-ev</c> with its <c>seqnum</c> per new message), with .NET's own HTTP and WebSocket clients.
/// </summary>
public sealed class RwsDataSubscriptionTests : IAsyncLifetime
{
    private static readonly TimeSpan Limit = TimeSpan.FromSeconds(20);
    private static readonly XNamespace X = "http://www.w3.org/1999/xhtml";
    private readonly RapidTwinController _twin = new();
    private readonly RwsTwinServer _rws;
    private readonly CookieContainer _cookies = new();
    private readonly HttpClient _http;

    public RwsDataSubscriptionTests()
    {
        _twin.Load(("Cell.mod", """
            MODULE Cell
              PERS num partCount := 0;
              VAR num scratch := 0;
              PROC main()
                WaitUntil partCount = 1;
                partCount := 2;
                ErrWrite \W, "Part counted", "The cell counted part " + NumToStr(partCount, 0);
                WaitUntil partCount = 3;
              ENDPROC
            ENDMODULE
            """));
        _rws = new RwsTwinServer(_twin);
        _rws.Start();
        _http = RwsTestClient.For(_rws.Port, _cookies, Limit);
    }

    public Task InitializeAsync() => Task.CompletedTask;

    public async Task DisposeAsync()
    {
        _http.Dispose();
        await _rws.DisposeAsync();
        Assert.True(_twin.StopTasks(TimeSpan.FromSeconds(10)), "the RAPID tasks to stop");
    }

    private Task<HttpResponseMessage> Subscribe(params string[] resources) => _http.PostAsync("/subscription", new FormUrlEncodedContent(
        resources.SelectMany((r, i) => new KeyValuePair<string, string>[] { new("resources", $"{i + 1}"), new($"{i + 1}", r), new($"{i + 1}-p", "1") })));

    private async Task<ClientWebSocket> OpenAsync(Uri poll, CancellationToken cancellation)
    {
        var socket = new ClientWebSocket();
        socket.Options.Cookies = _cookies;
        socket.Options.AddSubProtocol("robapi2_subscription");
        await socket.ConnectAsync(poll, cancellation);
        return socket;
    }

    private static async Task<XElement[]> NextEvent(ClientWebSocket socket, CancellationToken cancellation)
    {
        var buffer = new byte[64 * 1024];
        WebSocketReceiveResult result = await socket.ReceiveAsync(buffer, cancellation);
        Assert.Equal(WebSocketMessageType.Text, result.MessageType);
        return [.. XDocument.Parse(Encoding.UTF8.GetString(buffer, 0, result.Count)).Descendants(X + "li")];
    }

    private static string Span(XElement item, string cls) =>
        item.Elements().Single(e => e.Name.LocalName == "span" && (string?)e.Attribute("class") == cls).Value;

    private static string Self(XElement item) => (string)item.Elements().First(e => e.Name.LocalName == "a").Attribute("href")!;

    [Fact]
    public async Task APersistentVariable_SendsItsValueEachTimeItChanges_AndTheEventLog_EachNewMessage()
    {
        using var cancellation = new CancellationTokenSource(Limit);
        const string resource = "/rw/rapid/symbol/data/RAPID/T_ROB1/Cell/partCount;value";
        using HttpResponseMessage created = await Subscribe(resource, "/rw/elog/0");
        Assert.Equal(HttpStatusCode.Created, created.StatusCode);
        using ClientWebSocket socket = await OpenAsync(created.Headers.Location!, cancellation.Token);
        _twin.StartTasks();

        // A client writes the PERS (as RWS does): the event names it and carries the value.
        using HttpResponseMessage master = await _http.PostAsync("/rw/mastership?action=request", new FormUrlEncodedContent([]), cancellation.Token);
        using HttpResponseMessage set = await _http.PostAsync("/rw/rapid/symbol/data/RAPID/T_ROB1/Cell/partCount?action=set",
            new FormUrlEncodedContent([new("value", "1")]), cancellation.Token);
        Assert.Equal(HttpStatusCode.NoContent, set.StatusCode);

        // Each event the program's answer makes: partCount 2 (maybe after 1, if the twin looked in between), then its ErrWrite.
        var values = new List<string>();
        XElement? message = null;
        while (message is null)
        {
            foreach (XElement item in await NextEvent(socket, cancellation.Token))
            {
                switch ((string?)item.Attribute("class"))
                {
                    case "rap-value-ev":
                        Assert.Equal("value", (string?)item.Attribute("title"));
                        Assert.Equal(resource, Self(item));
                        break;
                    case "rap-data":
                        Assert.Equal("RAPID/T_ROB1/Cell/partCount", (string?)item.Attribute("title"));
                        values.Add(Span(item, "value"));
                        break;
                    case "elog-message-ev":
                        message = item;
                        break;
                    default:
                        Assert.Fail($"an unexpected event {item}");
                        break;
                }
            }
        }
        Assert.Equal("2", values[^1]);
        Assert.All(values, v => Assert.Contains(v, new[] { "1", "2" }));
        Assert.Equal("1", Span(message, "seqnum"));
        Assert.Equal("/rw/elog/0/1", Self(message));
        Assert.Equal((80002, "Part counted"), Assert.Single(_rws.EventLog));
    }

    [Fact]
    public async Task AVariableThatIsNotPersistent_IsRefused()
    {
        using HttpResponseMessage refused = await Subscribe("/rw/rapid/symbol/data/RAPID/T_ROB1/Cell/scratch;value");

        Assert.Equal(HttpStatusCode.BadRequest, refused.StatusCode);
        Assert.Contains("/rw/rapid/symbol/data/RAPID/TASK/MODULE/NAME;value of a PERS", await refused.Content.ReadAsStringAsync(), StringComparison.Ordinal);
    }
}
