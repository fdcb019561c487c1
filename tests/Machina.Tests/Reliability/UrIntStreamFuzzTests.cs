namespace Machina.Tests.Reliability;

/// <summary>
/// Seeded fuzzing of the host's reader of the UR driver's int32 stream of acknowledgements and responses
/// (<see cref="UrDriverReader"/>, what <c>UrDriver</c> receives; the virtual UR reads instructions only by running the driver
/// script). Each case is fed whole, one byte at a time (a cut at every byte boundary) and cut at a random point; all must read
/// the same, and only the documented error may come out.
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
}
