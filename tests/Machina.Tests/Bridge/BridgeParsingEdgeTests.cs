using System.Text;
using System.Text.Json;
using Machina.Bridge;

namespace Machina.Tests.Bridge;

/// <summary>
/// More edges of the bridge's HTTP head reader, its responses and the frame handler that mutation testing found untested,
/// with exact bytes and answers.
/// </summary>
public class BridgeParsingEdgeTests
{
    private static HttpRequestHead? Parse(string head, out string? error) => HttpRequestHead.TryParse(Encoding.Latin1.GetBytes(head), out error);

    private static async Task<(string? Head, bool TooLong)> ReadHead(string bytes)
    {
        (byte[]? head, bool tooLong) = await HttpConnection.ReadHeadAsync(new MemoryStream(Encoding.Latin1.GetBytes(bytes)), CancellationToken.None);
        return (head is null ? null : Encoding.Latin1.GetString(head), tooLong);
    }

    [Theory]
    [InlineData("GET / HTTP/1.1\nHost: x\n\nbody", "GET / HTTP/1.1\nHost: x\n\n")]
    [InlineData("GET / HTTP/1.1\r\n\r\nrest", "GET / HTTP/1.1\r\n\r\n")]
    [InlineData("GET / HTTP/1.1\r\nX: a\rb\r\n\r\n", "GET / HTTP/1.1\r\nX: a\rb\r\n\r\n")]
    [InlineData("\n\nGET", "\n\n")]
    public async Task ReadHead_EndsAtTheFirstEmptyLine_NothingAfterIt(string bytes, string expected) =>
        Assert.Equal((expected, false), await ReadHead(bytes));

    [Theory]
    [InlineData("GET / HTTP/1.1\r\nHost: x\r\n")]
    [InlineData("GET / HTTP/1.1\r\nX: a\nb\n")] // a line between the two line ends: not an empty line
    [InlineData("")]
    public async Task ReadHead_ClientClosesBeforeTheEmptyLine_Null(string bytes) => Assert.Equal((null, false), await ReadHead(bytes));

    [Fact]
    public void Head_LfLineEnds_TrailingEmptyLines_ValuesTrimmed_RepeatedJoined()
    {
        HttpRequestHead request = Parse("POST /p?x=1 HTTP/1.0\nHost:  example \nX-A: one\r\nx-a:two\n\n\n", out string? error)!;
        Assert.Null(error);
        Assert.Equal(("POST", "/p", "x=1"), (request.Method, request.Path, request.Query));
        Assert.Equal("example", request["HOST"]);
        Assert.Equal("one, two", request["X-A"]);
        Assert.Null(request["X-B"]);
    }

    [Theory]
    [InlineData("keep-alive, Upgrade", "upgrade", true)]
    [InlineData("Upgrade", "UPGRADE", true)]
    [InlineData("  upgrade  ,x", "Upgrade", true)]
    [InlineData("Upgraded", "Upgrade", false)]
    [InlineData("keep-alive", "Upgrade", false)]
    public void HasToken_CommaSeparatedAnyCase(string value, string token, bool expected)
    {
        HttpRequestHead request = Parse($"GET / HTTP/1.1\r\nConnection: {value}\r\n\r\n", out _)!;
        Assert.Equal(expected, request.HasToken("connection", token));
        Assert.False(request.HasToken("Upgrade", token)); // a header that is absent
    }

    [Fact]
    public void QueryValue_FirstOfRepeated_KeysDecodedToo()
    {
        HttpRequestHead request = Parse("GET /Bridge?a+b=1&a%20b=2&c=%3D%26&=empty&d=x=y HTTP/1.1\r\n\r\n", out _)!;
        Assert.Equal("1", request.QueryValue("a b"));
        Assert.Equal("=&", request.QueryValue("c"));
        Assert.Equal("empty", request.QueryValue(""));
        Assert.Equal("x=y", request.QueryValue("d"));
    }

    [Theory]
    [InlineData("GET  HTTP/1.1", "the request target must be a path such as /Bridge")]
    [InlineData("GET /a\tb HTTP/1.1", "the request target must be a path such as /Bridge")]
    [InlineData("GET /a\u0001 HTTP/1.1", "the request target must be a path such as /Bridge")]
    [InlineData("GET / HTTP/1.1 x", "the request line is not 'METHOD /path HTTP/1.1'")]
    [InlineData("GET / HTTP/1.10", "only HTTP/1.1 is served")]
    [InlineData("\r\n", "the request is empty")]
    public void RequestLine_MoreRefusals(string line, string expected)
    {
        Assert.Null(Parse(line + "\r\n\r\n", out string? error));
        Assert.Equal(expected, error);
    }

    [Theory]
    [InlineData("GET /~a-b_c.d!$'()*,;:@ HTTP/1.1", "/~a-b_c.d!$'()*,;:@", "")]
    [InlineData("GET /a#b?c=d HTTP/1.1", "/a", "")]
    [InlineData("GET /?#x HTTP/1.1", "/", "")]
    [InlineData("GET /a?b?c HTTP/1.1", "/a", "b?c")]
    [InlineData("M-._~!#$%&'*+^`| / HTTP/1.0", "/", "")]
    public void Target_PathAndQuery(string line, string path, string query)
    {
        HttpRequestHead request = Parse(line + "\r\n\r\n", out string? error)!;
        Assert.Null(error);
        Assert.Equal((path, query), (request.Path, request.Query));
    }

    [Theory]
    [InlineData("X: a\u001fb", "header line 1 holds a control character")]
    [InlineData("X: a\u0000", "header line 1 holds a control character")]
    [InlineData("X(: a", "header line 1 is not 'Name: value'")]
    [InlineData("X\u00e9: a", "header line 1 is not 'Name: value'")]
    public void Header_MoreRefusals(string header, string expected)
    {
        Assert.Null(Parse($"GET / HTTP/1.1\r\n{header}\r\n\r\n", out string? error));
        Assert.Equal(expected, error);
    }

    [Theory]
    [InlineData("X: a\u0080\u00ffb~ ", "a\u0080\u00ffb~")] // bytes above DEL pass through as Latin-1
    [InlineData("X:", "")]
    [InlineData("X: \t ", "")]
    public void Header_ValuesAccepted(string header, string value)
    {
        HttpRequestHead request = Parse($"GET / HTTP/1.1\r\n{header}\r\n\r\n", out string? error)!;
        Assert.Null(error);
        Assert.Equal(value, request["x"]);
    }

    [Fact]
    public void Response_ExactBytes_HeadOnlyLeavesTheBodyOutButCountsIt()
    {
        const string head = "HTTP/1.1 200 OK\r\nContent-Type: text/plain\r\nContent-Length: 3\r\nCache-Control: no-store\r\n" +
            "X-Content-Type-Options: nosniff\r\nConnection: close\r\nX-Frame-Options: DENY\r\n\r\n";
        Assert.Equal(head + "abc", Encoding.ASCII.GetString(HttpConnection.Response(200, "OK", "text/plain", "abc"u8, "X-Frame-Options: DENY\r\n")));
        Assert.Equal(head, Encoding.ASCII.GetString(HttpConnection.Response(200, "OK", "text/plain", "abc"u8, "X-Frame-Options: DENY\r\n", headOnly: true)));
    }

    [Fact]
    public void Error_PlainTextUtf8WithALineEnd()
    {
        byte[] bytes = HttpConnection.Error(403, "Forbidden", "Nein: \u00fc", "X: y\r\n");
        Assert.Equal("HTTP/1.1 403 Forbidden\r\nContent-Type: text/plain; charset=utf-8\r\nContent-Length: 9\r\nCache-Control: no-store\r\n" +
            "X-Content-Type-Options: nosniff\r\nConnection: close\r\nX: y\r\n\r\nNein: \u00fc\n", Encoding.UTF8.GetString(bytes));
    }

    [Fact]
    public void SwitchingProtocols_TheRfc6455Example()
    {
        Assert.Equal("s3pPLMBiTxaQ9kYGzzhZRbK+xOo=", HttpConnection.AcceptKey("dGhlIHNhbXBsZSBub25jZQ=="));
        Assert.Equal("HTTP/1.1 101 Switching Protocols\r\nUpgrade: websocket\r\nConnection: Upgrade\r\nSec-WebSocket-Accept: s3pPLMBiTxaQ9kYGzzhZRbK+xOo=\r\n\r\n",
            Encoding.ASCII.GetString(HttpConnection.SwitchingProtocols("dGhlIHNhbXBsZSBub25jZQ==")));
    }

    [Theory]
    [InlineData("", true)]
    [InlineData(" \t\r\n;;\uFEFF", true)]
    [InlineData("// only a comment", true)]
    [InlineData("// a comment\n  ; // another\n", true)]
    [InlineData("/", false)]
    [InlineData("/ /", false)]
    [InlineData("// a comment\nMoveTo(1,2,3);", false)]
    [InlineData("x", false)]
    [InlineData(";\u00a0;", true)] // a no-break space is white space
    public void HoldsNoInstruction_OnlyWhatTheReaderSkips(string text, bool expected) => Assert.Equal(expected, FrameHandler.HoldsNoInstruction(text));

    private static (string Kind, string Message) ErrorOf(string? reply)
    {
        using JsonDocument json = JsonDocument.Parse(reply!);
        Assert.Equal("error", json.RootElement.GetProperty("event").GetString());
        return (json.RootElement.GetProperty("kind").GetString()!, json.RootElement.GetProperty("message").GetString()!);
    }

    [Fact]
    public void Handle_Outcomes_ExactReplies()
    {
        var robot = Robot.Create("Edge", RobotType.ABB);
        bool connected = false;
        var handler = new FrameHandler(robot, () => connected);
        int issued = 0;
        robot.ActionIssued += (_, _) => issued++;
        Assert.Equal(new FrameResult(FrameOutcome.NoController, "{\"event\":\"controller-disconnected\"}"), handler.Handle("MoveTo(400,300,500);"));
        Assert.Equal(0, issued);
        connected = true;
        FrameResult empty = handler.Handle(" // nothing\n;");
        Assert.Equal(FrameOutcome.Rejected, empty.Outcome);
        Assert.Equal(("empty", "The message holds no instruction; send text such as MoveTo(400,300,500);"), ErrorOf(empty.Reply));
        FrameResult parse = handler.Handle("MoveTo(1,2;");
        Assert.Equal(FrameOutcome.Rejected, parse.Outcome);
        Assert.Equal("parse", ErrorOf(parse.Reply).Kind);
        FrameResult refused = handler.Handle("MoveTo(400,300,500); AttachTool(\"ghost\");");
        Assert.Equal(FrameOutcome.Rejected, refused.Outcome);
        Assert.Equal("refused", ErrorOf(refused.Reply).Kind);
        Assert.Equal(0, issued); // none of the message
        Assert.Equal(new FrameResult(FrameOutcome.Accepted, null), handler.Handle("MoveTo(400,300,500); Wait(10);"));
        Assert.Equal(2, issued);
        Assert.Throws<ArgumentNullException>(() => handler.Handle(null!));
    }
}
