using System.Text;

namespace Machina.Tests.Programs;

public class AsciiFileSinkTests
{
    // Lines of every kind a compiler gives: plain, empty, non-ASCII (a surrogate pair, a lone surrogate), longer than the buffer,
    // and builders of several chunks, some of them non-ASCII.
    private static readonly string[] Lines =
    [
        "  movel(p[0.1, 0.2, 0.3, 0, 3.1416, 0], a=1.2, v=0.25)",
        "",
        "unicodé ✓ 日本 🤖 end",
        "lone \uD83E high and \uDD16 low",
        new string('x', 700) + "é" + new string('y', 300),
        "tail",
    ];

    private static StringBuilder Builder(params string[] parts)
    {
        var builder = new StringBuilder(4);
        foreach (string part in parts)
        {
            builder.Append(part);
        }
        return builder;
    }

    private static void Feed(LineSink sink)
    {
        foreach (string line in Lines)
        {
            sink.Add(line);
            sink.Add(line.AsSpan());
        }
        sink.Add(Builder("  # warning: ", "short move ", new string('z', 40)));
        sink.Add(Builder("ab", "cd ✓ ", "🤖", "ef"));
        sink.Add(Builder(new string('w', 600), "v"));
    }

    private static byte[] WithStreamWriter(string newLine)
    {
        var bytes = new MemoryStream();
        using (var writer = new StreamWriter(bytes, Encoding.ASCII, 1 << 16, leaveOpen: true))
        {
            Feed(new WriterLineSink(writer, newLine));
        }
        return bytes.ToArray();
    }

    [Theory]
    [InlineData("\n")]
    [InlineData("\r\n")]
    public void Add_EveryKindOfLine_WritesTheBytesOfAStreamWriterInAscii(string newLine)
    {
        var bytes = new MemoryStream();
        var sink = new AsciiFileSink(bytes, newLine, bufferSize: 256);
        Feed(sink);
        byte[] written = bytes.ToArray();
        sink.Flush();

        Assert.Equal(WithStreamWriter(newLine), bytes.ToArray());
        Assert.True(written.Length < bytes.ToArray().Length); // the last bytes waited in the buffer until Flush
        Assert.Contains((byte)'?', bytes.ToArray());
    }

    [Fact]
    public void StartOver_AfterLines_DropsThemAndTheBufferedBytes()
    {
        var bytes = new MemoryStream();
        var sink = new AsciiFileSink(bytes, "\n", bufferSize: 256);
        sink.Add(new string('a', 300)); // written out
        sink.Add("buffered");

        Assert.True(sink.CanStartOver);
        sink.StartOver();
        sink.Add("again");
        sink.Flush();

        Assert.Equal("again\n", Encoding.ASCII.GetString(bytes.ToArray()));
    }

    [Fact]
    public void FileSpool_Ascii_MovesIntoAnAsciiFileAsBytesAndIntoOtherSinksLineByLine()
    {
        string path = Path.Combine(Path.GetTempPath(), "machina-test-" + Guid.NewGuid().ToString("N") + ".spool");
        using var spool = new FileSpool(path, Encoding.ASCII, "\r\n");
        spool.Add("first");
        spool.Add("second ✓".AsSpan());
        var file = new MemoryStream();
        var sink = new AsciiFileSink(file, "\r\n");
        sink.Add("head");

        spool.MoveTo(sink);
        sink.Add("foot");
        sink.Flush();
        spool.Add("third");
        var list = new ListLineSink();
        spool.MoveTo(list);

        Assert.Equal("head\r\nfirst\r\nsecond ?\r\nfoot\r\n", Encoding.ASCII.GetString(file.ToArray()));
        Assert.Equal(["third"], list.Lines);
    }

    /// <summary>Lines given as ASCII bytes (<see cref="LineSink.BeginAscii"/>) among lines of characters, and one begun and never ended.</summary>
    private static void FeedBytes(LineSink sink)
    {
        sink.Add("first");
        foreach (string line in (string[])["  LIN {E6POS: X 1.5}", "", new string('b', 400), "last of bytes"])
        {
            Span<byte> room = sink.BeginAscii(line.Length + 8);
            Assert.True(room.Length >= line.Length + 8);
            Encoding.ASCII.GetBytes(line, room);
            sink.EndAscii(line.Length);
            sink.Add(line + " as characters");
        }
        Encoding.ASCII.GetBytes("dropped", sink.BeginAscii(32)); // never ended: not a line
        sink.Add("end");
    }

    private static readonly string[] FedByBytes =
    [
        "first", "  LIN {E6POS: X 1.5}", "  LIN {E6POS: X 1.5} as characters", "", " as characters", new string('b', 400),
        new string('b', 400) + " as characters", "last of bytes", "last of bytes as characters", "end",
    ];

    [Theory]
    [InlineData("\n")]
    [InlineData("\r\n")]
    public void BeginAscii_LinesOfBytesAmongLinesOfCharacters_WrittenInOrderInPlace(string newLine)
    {
        var bytes = new MemoryStream();
        var sink = new AsciiFileSink(bytes, newLine, bufferSize: 256); // a line longer than the buffer, and flushes between lines
        FeedBytes(sink);
        sink.Flush();

        Assert.Equal(string.Concat(FedByBytes.Select(line => line + newLine)), Encoding.ASCII.GetString(bytes.ToArray()));
    }

    [Fact]
    public void BeginAscii_SinksOfLinesAndOfCharacters_TheSameLinesInOrder()
    {
        var list = new ListLineSink();
        FeedBytes(list);
        var text = new StringWriter();
        FeedBytes(new WriterLineSink(text, "\n"));

        Assert.Equal(FedByBytes, list.Lines);
        Assert.Equal(string.Concat(FedByBytes.Select(line => line + "\n")), text.ToString());
    }
}
