namespace Machina.Tests.Brands.Abb;

/// <summary>The SpeedTo pre-scan of a RAPID compile stops when the compile's token is cancelled, as MayContain does.</summary>
public class RapidSpeedScanTests
{
    [Fact]
    public void Of_TokenCancelledDuringTheScan_StopsAtTheNextBlock()
    {
        // 40,000 lines (about 1 MB, some 16 blocks of 64 K characters) with a speed near the end; the token is cancelled
        // when the reader hands out its second piece.
        string text = string.Concat(Enumerable.Repeat("Move(1.25, -2.5, 0.125);\n", 40_000)) + "SpeedTo(50);\nMove(1, 1, 1);\n";
        using var cancel = new CancellationTokenSource();
        CountingReader? reader = null;
        var source = new InstructionSource(() => reader = new CountingReader(text, cancel, cancelAtRead: 2), cancel.Token);

        Assert.Throws<OperationCanceledException>(() => RapidSpeedScan.Of(source));
        Assert.NotNull(reader);
        // Stopped right after the read that cancelled it: far from the text's end.
        Assert.Equal(2, reader!.Reads);
        Assert.True(reader.Position < text.Length / 4, $"read {reader.Position} of {text.Length} characters");
    }

    [Fact]
    public void Of_TokenCancelledBefore_ReadsOneBlockAtMost()
    {
        using var cancel = new CancellationTokenSource();
        cancel.Cancel();
        CountingReader? reader = null;
        var source = new InstructionSource(() => reader = new CountingReader("SpeedTo(50);\nMove(1, 1, 1);\n", cancel, cancelAtRead: 0), cancel.Token);

        Assert.Throws<OperationCanceledException>(() => RapidSpeedScan.Of(source));
        Assert.Equal(1, reader!.Reads);
    }

    [Fact]
    public void Of_NotCancelled_FindsTheSpeedsAfterManyBlocks()
    {
        string text = string.Concat(Enumerable.Repeat("Move(1.25, -2.5, 0.125);\n", 40_000)) + "SpeedTo(50);\nMove(1, 1, 1);\n";
        using var cancel = new CancellationTokenSource();
        var source = new InstructionSource(() => new StringReader(text), cancel.Token);

        RapidSpeedScan? scan = RapidSpeedScan.Of(source);

        Assert.NotNull(scan);
        Assert.Equal([50.0], scan!.Speeds);
        Assert.True(scan.StartSpeedMoves);
    }

    /// <summary>A reader of a text that counts its reads and cancels a token at one of them.</summary>
    private sealed class CountingReader(string text, CancellationTokenSource cancel, int cancelAtRead) : TextReader
    {
        internal int Reads { get; private set; }

        internal int Position { get; private set; }

        public override int Read(char[] buffer, int index, int count) => Read(buffer.AsSpan(index, count));

        public override int Read(Span<char> buffer)
        {
            Reads++;
            if (Reads == cancelAtRead)
            {
                cancel.Cancel();
            }
            int n = Math.Min(buffer.Length, text.Length - Position);
            text.AsSpan(Position, n).CopyTo(buffer);
            Position += n;
            return n;
        }

        public override int ReadBlock(char[] buffer, int index, int count) => Read(buffer.AsSpan(index, count));

        public override int ReadBlock(Span<char> buffer) => Read(buffer);

        public override int Peek() => Position < text.Length ? text[Position] : -1;

        public override int Read() => Position < text.Length ? text[Position++] : -1;
    }
}
