using System.Text;
using Machina.Bridge;
using static Machina.Tests.Bridge.BridgeTestSupport;

namespace Machina.Tests.Bridge;

/// <summary>The request parser's edges that mutation testing found untested, with the exact answers.</summary>
public class BridgeParserTests
{
    private static HttpRequestHead? Parse(string head, out string? error) => HttpRequestHead.TryParse(Encoding.Latin1.GetBytes(head), out error);

    [Theory]
    [InlineData("Host: a\u0001b", "header line 1 holds a control character")]
    [InlineData("Host: x\r\nX-Name: a\u007fb", "header line 2 holds a control character")]
    [InlineData("Host: x\r\nX-Name: a\u001bb", "header line 2 holds a control character")]
    [InlineData("Bad Name: x", "header line 1 is not 'Name: value'")]
    [InlineData(": x", "header line 1 is not 'Name: value'")]
    [InlineData("NoColon", "header line 1 is not 'Name: value'")]
    public void Header_Refused_WithTheLineAndReason(string headers, string expected)
    {
        Assert.Null(Parse($"GET / HTTP/1.1\r\n{headers}\r\n\r\n", out string? error));
        Assert.Equal(expected, error);
    }

    [Fact]
    public void Header_TabInValue_Accepted_AndTrimmed()
    {
        HttpRequestHead request = Parse("GET / HTTP/1.1\r\nX-A: \ta\tb \r\n\r\n", out _)!;
        Assert.Equal("a\tb", request["x-a"]);
    }

    [Theory]
    [InlineData("", "the request is empty")]
    [InlineData("GET /  HTTP/1.1", "the request line is not 'METHOD /path HTTP/1.1'")]
    [InlineData("GET /", "the request line is not 'METHOD /path HTTP/1.1'")]
    [InlineData(" / HTTP/1.1", "the request line is not 'METHOD /path HTTP/1.1'")]
    [InlineData("G(T / HTTP/1.1", "the request line is not 'METHOD /path HTTP/1.1'")]
    [InlineData("GET / HTTP/2.0", "only HTTP/1.1 is served")]
    [InlineData("GET / http/1.1", "only HTTP/1.1 is served")]
    [InlineData("GET http://x/Bridge HTTP/1.1", "the request target must be a path such as /Bridge")]
    [InlineData("GET /a\u00e9 HTTP/1.1", "the request target must be a path such as /Bridge")]
    [InlineData("GET /a\u007f HTTP/1.1", "the request target must be a path such as /Bridge")]
    public void RequestLine_Refused_WithTheReason(string line, string expected)
    {
        Assert.Null(Parse(line.Length == 0 ? "\r\n" : $"{line}\r\nHost: x\r\n\r\n", out string? error));
        Assert.Equal(expected, error);
    }

    [Fact]
    public async Task RequestLine_Refused_Answered400WithTheReason()
    {
        await using BridgeServer bridge = await StartAsync();
        Assert.Equal(RawHttp.Expected(400, "Bad Request", "Bad request: only HTTP/1.1 is served."), await RawHttp.RequestAsync(bridge.Port, "GET / HTTP/2.0\r\n\r\n"));
        Assert.Equal(RawHttp.Expected(400, "Bad Request", "Bad request: the request target must be a path such as /Bridge."),
            await RawHttp.RequestAsync(bridge.Port, "GET * HTTP/1.1\r\n\r\n"));
        Assert.Equal(RawHttp.Expected(400, "Bad Request", "Bad request: header line 1 holds a control character."),
            await RawHttp.RequestAsync(bridge.Port, "GET / HTTP/1.1\r\nHost: a\u0001b\r\n\r\n"));
        Assert.Equal(RawHttp.Expected(400, "Bad Request", "Bad request: the request has too many headers."),
            await RawHttp.RequestAsync(bridge.Port, "GET / HTTP/1.1\r\n" + string.Concat(Enumerable.Range(0, 101).Select(i => $"X-{i}: v\r\n")) + "\r\n"));
        Assert.Equal(RawHttp.Expected(400, "Bad Request", "Sec-WebSocket-Key must be 16 bytes in base64."), await RawHttp.RequestAsync(bridge.Port,
            "GET /Bridge HTTP/1.1\r\nHost: x\r\nUpgrade: websocket\r\nConnection: Upgrade\r\nSec-WebSocket-Version: 13\r\nSec-WebSocket-Key: AAAAAAAAAAAAAAAAAAAAAAA=\r\n\r\n"));
        Assert.Equal(RawHttp.Expected(431, "Request Header Fields Too Large", "The request head is too long."),
            await RawHttp.RequestAsync(bridge.Port, "GET / HTTP/1.1\r\nX: " + new string('a', HttpRequestHead.MaxBytes) + "\r\n\r\n"));
    }

    [Fact]
    public void Path_WithoutQuestionMark_EmptyQuery_AndFragmentDropped()
    {
        HttpRequestHead request = Parse("GET /Bridge HTTP/1.1\r\n\r\n", out _)!;
        Assert.Equal("/Bridge", request.Path);
        Assert.Equal("", request.Query);
        Assert.Null(request.QueryValue("name"));
        HttpRequestHead withFragment = Parse("GET /Bridge?name=a#b=c HTTP/1.1\r\n\r\n", out _)!;
        Assert.Equal("name=a", withFragment.Query);
        Assert.Null(withFragment.QueryValue("b"));
    }

    [Fact]
    public void Parameter_WithoutEquals_IsEmpty_OthersDecoded()
    {
        HttpRequestHead request = Parse("GET /Bridge?flag&name=Grass+hopper%21&name=second&authkey= HTTP/1.1\r\n\r\n", out _)!;
        Assert.Equal("", request.QueryValue("flag"));
        Assert.Equal("Grass hopper!", request.QueryValue("name"));
        Assert.Equal("", request.QueryValue("authkey"));
        Assert.Null(request.QueryValue("fla"));
    }

    [Fact]
    public void Headers_100Accepted_101Refused()
    {
        string Head(int n) => "GET / HTTP/1.1\r\n" + string.Concat(Enumerable.Range(0, n).Select(i => $"X-{i}: v{i}\r\n")) + "\r\n";
        HttpRequestHead hundred = Parse(Head(HttpRequestHead.MaxHeaders), out string? none)!;
        Assert.Null(none);
        Assert.Equal("v99", hundred["x-99"]);
        Assert.Null(Parse(Head(HttpRequestHead.MaxHeaders + 1), out string? error));
        Assert.Equal("the request has too many headers", error);
    }

    [Fact]
    public async Task Head_Of16KiB_Read_OneByteMore_TooLong()
    {
        string Head(int length)
        {
            const string start = "GET / HTTP/1.1\r\nX: ";
            return start + new string('a', length - start.Length - 4) + "\r\n\r\n";
        }
        byte[] exact = Encoding.ASCII.GetBytes(Head(HttpRequestHead.MaxBytes));
        Assert.Equal(16 * 1024, exact.Length);
        (byte[]? read, bool tooLong) = await HttpConnection.ReadHeadAsync(new MemoryStream([.. exact, .. "rest"u8.ToArray()]), CancellationToken.None);
        Assert.False(tooLong);
        Assert.Equal(exact, read); // nothing after the blank line is consumed
        Assert.NotNull(HttpRequestHead.TryParse(read, out _));
        byte[] over = Encoding.ASCII.GetBytes(Head(HttpRequestHead.MaxBytes + 1));
        (read, tooLong) = await HttpConnection.ReadHeadAsync(new MemoryStream(over), CancellationToken.None);
        Assert.True(tooLong);
        Assert.Null(read);
        Assert.Null(HttpRequestHead.TryParse(over, out string? error));
        Assert.Equal("the request head is too long", error);
    }

    [Theory]
    [InlineData("dGhlIHNhbXBsZSBub25jZQ==", true)]
    [InlineData("AAAAAAAAAAAAAAAAAAAAAA==", true)]
    [InlineData("AAAAAAAAAAAAAAAAAAAAAAA=", false)] // 24 characters, 17 bytes
    [InlineData("AAAAAAAAAAAAAAAAAAAAAAAA", false)] // 24 characters, 18 bytes
    [InlineData("AAAAAAAAAAAAAAAAAAAAA===", false)] // 24 characters, not base64
    [InlineData("AAAAAAAAAAAAAAAAAAAAAA=", false)]
    [InlineData(null, false)]
    public void Key_MustDecodeToSixteenBytes(string? key, bool valid) => Assert.Equal(valid, HttpConnection.IsValidKey(key));
}
