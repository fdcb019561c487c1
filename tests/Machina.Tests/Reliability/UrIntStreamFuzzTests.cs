using System.Buffers.Binary;
using Machina.Simulation;

namespace Machina.Tests.Reliability;

/// <summary>
/// Seeded fuzzing of both readers of the UR driver's int32 streams: the host's reader of acknowledgements and responses
/// (<see cref="UrDriverReader"/>, what <c>UrDriver</c> receives) and the virtual UR's reader of instructions
/// (<see cref="UrRequestReader"/>). Each case is fed whole, one byte at a time (a cut at every byte boundary) and cut at a
/// random point; all must read the same, and only the documented error may come out.
/// </summary>
public class UrIntStreamFuzzTests
{
    /// <summary>Values a stream is built from: acknowledgements, response codes and markers, instruction codes, and the int32 edges.</summary>
    private static readonly int[] Interesting =
    [
        1, 2, 3, 7, 12, 13, 14, 17, 42, 0, -1, -2, UrWire.ResponseVersion, UrWire.ResponseFullPose, UrWire.End, int.MaxValue, -1000, 1 << 24,
    ];

    /// <summary>Random values: mostly interesting ones, some anything.</summary>
    private static int[] Values(Random random, int maxCount)
    {
        var values = new int[random.Next(maxCount + 1)];
        for (int i = 0; i < values.Length; i++)
        {
            values[i] = random.Next(4) == 0 ? random.Next(int.MinValue, int.MaxValue) : Interesting[random.Next(Interesting.Length)];
        }
        return values;
    }

    private static byte[] Bytes(int[] values)
    {
        var bytes = new byte[values.Length * 4];
        UrWire.Write(values, bytes);
        return bytes;
    }

    /// <summary>The i-th case: half streams of values (truncated at a random byte now and then), half valid streams mutated bytewise.</summary>
    private static byte[] Case(Random random, int i, int[][] valid)
    {
        if (i % 16 == 2)
        {
            // A response whose end marker never comes (a huge count of values).
            return Bytes([.. Values(random, 10), UrWire.ResponseFullPose, .. Values(random, 120).Where(v => v != UrWire.End).Append(1).Take(60 + random.Next(60))]);
        }
        if (i % 2 == 0)
        {
            byte[] bytes = Bytes(Values(random, 40));
            return i % 8 == 0 ? bytes[..random.Next(bytes.Length + 1)] : bytes;
        }
        return Fuzz.Mutate(random, Bytes(valid[random.Next(valid.Length)]), [0, 0x80, 0xFF, 0xFF, 0xCE, 1, 2, 3, 0x7F]);
    }

    private static readonly int[][] FromDriver =
    [
        [UrWire.ResponseVersion, 2, 0, 0, UrWire.End, UrWire.ResponseFullPose, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, UrWire.End],
        [1, 2, 3, 4, 5], [UrWire.ResponseVersion, 2, 0, 0, UrWire.End, 7, 0, -1, 8],
    ];

    private static readonly int[][] ToDriver =
    [
        [1, 1, 4000, 0, 5000, 0, 31416, 0], [2, 4, 1000, 3, 3, 0, 0, 0, 0, 0, 15708, 0], [4, 9, 500, 5, 13, 1, 1, 0, 6, 14, 2, 500000],
        [7, 12, 0, 0, 1000, 0, 0, 0, 1000, 8, 17, 1, 2, 3, 4, 5, 6], [9, 99, 1, 2, 3],
    ];

    [Fact]
    public async Task UrDriverReader_RandomAndMutatedStreams_SameMessagesHoweverChunked_OrConnectionError()
    {
        var random = new Random(14_006);
        int acknowledgements = 0, responses = 0, refused = 0;
        await Fuzz.RunBoundedAsync(() =>
        {
            for (int i = 0; i < Fuzz.Cases; i++)
            {
                byte[] bytes = Case(random, i, FromDriver);
                string whole = ReadHost(bytes, [bytes.Length]);
                Assert.Equal(whole, ReadHost(bytes, [.. Enumerable.Repeat(1, bytes.Length)]));
                int cut = random.Next(bytes.Length + 1);
                Assert.Equal(whole, ReadHost(bytes, [cut, bytes.Length - cut]));
                acknowledgements += whole.Split(' ').Count(m => m.StartsWith('a'));
                responses += whole.Split(' ').Count(m => m.StartsWith('r'));
                refused += whole.EndsWith("refused", StringComparison.Ordinal) ? 1 : 0;
            }
        });
        Assert.InRange(acknowledgements, Fuzz.Cases, 100 * Fuzz.Cases);
        Assert.InRange(responses, Fuzz.Cases / 10, 100 * Fuzz.Cases);
        Assert.InRange(refused, 100, Fuzz.Cases / 2);
    }

    /// <summary>What a fresh reader makes of the bytes fed in pieces of the given lengths: "a5" per acknowledgement, "r-50x4" per response, "refused" at the end on the error.</summary>
    private static string ReadHost(byte[] bytes, int[] pieces)
    {
        var reader = new UrDriverReader();
        var read = new List<string>();
        int at = 0;
        try
        {
            foreach (int length in pieces)
            {
                ReadOnlySpan<byte> data = bytes.AsSpan(at, length);
                at += length;
                while (true)
                {
                    int before = data.Length;
                    if (!reader.TryRead(ref data, out int acknowledged, out int[]? response))
                    {
                        Assert.True(data.IsEmpty, "a read that finds nothing consumes everything");
                        break;
                    }
                    Assert.True(data.Length < before, "a read consumes bytes");
                    if (response is null)
                    {
                        Assert.True(acknowledged > 0);
                        read.Add("a" + acknowledged);
                    }
                    else
                    {
                        Assert.InRange(response.Length, 1, UrDriverReader.MaxResponseValues);
                        Assert.True(response[0] < -1 && !response.Contains(UrWire.End) || response[0] == UrWire.End && response.Skip(1).All(v => v != UrWire.End));
                        read.Add($"r{response[0]}x{response.Length}");
                    }
                }
            }
        }
        catch (RobotConnectionException e)
        {
            Assert.Contains("never ends", e.Message, StringComparison.Ordinal);
            read.Add("refused");
        }
        return string.Join(' ', read);
    }

    [Fact]
    public void UrDriverReader_EndlessResponse_RefusedAtItsBound()
    {
        var reader = new UrDriverReader();
        byte[] chunk = Bytes([UrWire.ResponseFullPose, .. Enumerable.Range(1, 1000)]);
        ReadOnlySpan<byte> data = chunk;
        RobotConnectionException? error = null;
        try
        {
            while (reader.TryRead(ref data, out _, out _))
            {
            }
        }
        catch (RobotConnectionException e)
        {
            error = e;
        }

        Assert.Equal("The UR driver sent a response longer than 64 values that never ends; is it Machina's driver?", error?.Message);
        Assert.Equal((1001 - 65) * 4, data.Length); // it stopped at the 65th value
    }

    [Fact]
    public async Task UrRequestReader_RandomAndMutatedStreams_SameRequestsHoweverChunked()
    {
        var random = new Random(14_007);
        int requests = 0, halts = 0, endedInside = 0;
        await Fuzz.RunBoundedAsync(() =>
        {
            for (int i = 0; i < Fuzz.Cases; i++)
            {
                byte[] bytes = Case(random, i, ToDriver);
                var kind = i % 5 == 0 ? VirtualUrController.DriverKind.Original : VirtualUrController.DriverKind.Ours;
                string whole = ReadVirtual(bytes, kind, bytes.Length + 1);
                Assert.Equal(whole, ReadVirtual(bytes, kind, 1));
                Assert.Equal(whole, ReadVirtual(bytes, kind, 1 + random.Next(bytes.Length + 1)));
                requests += whole.Split(';').Count(r => r.StartsWith(' ') || r.StartsWith('-') || char.IsDigit(r.FirstOrDefault()));
                halts += whole.Contains("halts", StringComparison.Ordinal) ? 1 : 0;
                endedInside += whole.Contains("ended inside", StringComparison.Ordinal) ? 1 : 0;
            }
        });
        Assert.InRange(requests, Fuzz.Cases, 100 * Fuzz.Cases);
        Assert.InRange(halts, Fuzz.Cases / 10, Fuzz.Cases);
        Assert.InRange(endedInside, Fuzz.Cases / 20, Fuzz.Cases);
    }

    /// <summary>What the virtual UR reads from the bytes served at most <paramref name="chunk"/> at a time: each request, then how it ended.</summary>
    private static string ReadVirtual(byte[] bytes, VirtualUrController.DriverKind kind, int chunk)
    {
        var reader = new UrRequestReader(new ChunkedStream(bytes, chunk), kind, 1);
        var read = new List<string>();
        for (int guard = 0; guard <= bytes.Length; guard++)
        {
            // Reads complete synchronously on this stream: no thread is needed, and a hang would show as a task never done.
            Task<UrRequest?> next = reader.ReadAsync(CancellationToken.None);
            Assert.True(next.IsCompleted, "a read of a finished stream waits for nothing");
            if (next.Result is not UrRequest request)
            {
                read.Add(reader.EndedInside is (int id, int code) ? $"ended inside {id} {code}" : "end");
                return string.Join(';', read);
            }
            Assert.Equal(Math.Max(VirtualUrController.ParameterCount(request.Code, kind), 0), request.Values.Length);
            if (request.Halts)
            {
                Assert.Equal(VirtualUrController.DriverKind.Ours, kind);
                read.Add(request + " halts");
                return string.Join(';', read);
            }
            read.Add(request.ToString());
        }
        Assert.Fail("more requests than bytes / 8");
        return "";
    }

    [Fact]
    public async Task UrRequestReader_StreamOfHugeValues_ReadsTheInstructionsItHolds()
    {
        // Code and parameter counts come from the code alone, never from a value: a "count" of int.MaxValue reads nothing extra.
        byte[] bytes = Bytes([int.MaxValue, 9, int.MaxValue, int.MinValue, 4, int.MinValue, 5, 13, int.MaxValue, -1, 0]);
        var reader = new UrRequestReader(new ChunkedStream(bytes, 3), VirtualUrController.DriverKind.Ours, 7);

        UrRequest? first = await reader.ReadAsync(CancellationToken.None);
        UrRequest? second = await reader.ReadAsync(CancellationToken.None);
        UrRequest? third = await reader.ReadAsync(CancellationToken.None);
        UrRequest? end = await reader.ReadAsync(CancellationToken.None);

        Assert.Equal("2147483647 9 2147483647", first!.ToString());
        Assert.Equal("-2147483648 4 -2147483648", second!.ToString());
        Assert.Equal("5 13 2147483647 -1 0", third!.ToString());
        Assert.Equal(7, third.Program);
        Assert.Null(end);
        Assert.Null(reader.EndedInside);
    }

    /// <summary>A read-only stream over bytes that returns at most <c>chunk</c> bytes per read, synchronously.</summary>
    private sealed class ChunkedStream(byte[] bytes, int chunk) : Stream
    {
        private int _at;

        public override bool CanRead => true;

        public override bool CanSeek => false;

        public override bool CanWrite => false;

        public override long Length => bytes.Length;

        public override long Position { get => _at; set => throw new NotSupportedException(); }

        public override int Read(byte[] buffer, int offset, int count) => Read(buffer.AsSpan(offset, count));

        public override int Read(Span<byte> buffer)
        {
            int n = Math.Min(Math.Min(chunk, buffer.Length), bytes.Length - _at);
            bytes.AsSpan(_at, n).CopyTo(buffer);
            _at += n;
            return n;
        }

        public override ValueTask<int> ReadAsync(Memory<byte> buffer, CancellationToken cancellationToken = default) => new(Read(buffer.Span));

        public override void Flush()
        {
        }

        public override long Seek(long offset, SeekOrigin origin) => throw new NotSupportedException();

        public override void SetLength(long value) => throw new NotSupportedException();

        public override void Write(byte[] buffer, int offset, int count) => throw new NotSupportedException();
    }
}
