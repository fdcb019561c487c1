using System.Text;
using Machina.Simulation;

namespace Machina.Tests.Reliability;

/// <summary>
/// Seeded fuzzing of every decoder that reads bytes from the other end of a link: the host's readers of the ABB, UR and KUKA
/// drivers, and the virtual controllers' readers of the host's requests. Each case is fed whole, then again cut at a random
/// point; the only allowed failure is the brand's protocol error, and every read must consume bytes (so no loop can spin).
/// </summary>
public class ProtocolDecoderFuzzTests
{
    private static readonly string[] AbbFromController =
    [
        "$20 1 4 2;$21 815 0 1075 0.7071 0 0.7071 0;$22 0 0 0 0 90 0;$23 9E9 9E9 1800 9E9 9E9 9E9;", "@12 1;15;@8388608 16;",
        "$24 100.5 -2 300 1 0 0 0>10 20 30 40 50 60>1.800E+03 9E9 9E9 9E9 9E9 9E9;", "$@5 101 2 192.168.125.1 7000;", "$26 3 5;",
    ];

    private static readonly string[] KukaXml =
    [
        "<?xml version=\"1.0\"?>\r\n<S VR=\"2.0\" A1=\"0\" A2=\"-90\" A3=\"90\" A4=\"0\" A5=\"0\" A6=\"0\" X=\"455\" Y=\"0\" Z=\"935\" A=\"0\" B=\"90\" C=\"0\" Executed=\"3\" Received=\"5\"></S>",
        "<R ID=\"1\"></R><R ID='2'/><!-- c -->", "<P A1=\"1\" A2=\"2\" A3=\"3\" A4=\"4\" A5=\"5\" A6=\"6\" X=\"1\" Y=\"2\" Z=\"3\" A=\"0\" B=\"0\" C=\"0\"/>",
        "<DT><DR><A ID=\"7\" T=\"1\" M=\"a &amp; b\" /></DR></DT>",
    ];

    private static readonly byte[] AbbAlphabet = Encoding.ASCII.GetBytes("@$;> -+.eE0123456789\"\r\n\tabc");
    private static readonly byte[] XmlAlphabet = Encoding.ASCII.GetBytes("<>/?!-=\"' &;#xamplqut RSPADTIM0123456789.\r\n");

    [Fact]
    public async Task AbbMessageReader_RandomAndMutatedBytes_MessagesOrAbbProtocolException()
    {
        var counts = await RunAsync(14_002, AbbFromController, AbbAlphabet, 120, () => new AbbMessageReader(), (reader, bytes) =>
        {
            reader.Append(bytes);
            int read = 0;
            while (true)
            {
                int before = reader.PendingByteCount;
                if (!reader.TryRead(out AbbMessage message))
                {
                    return read;
                }
                Assert.True(reader.PendingByteCount < before, "a read consumes bytes");
                Assert.NotNull(message.ToString());
                read++;
            }
        }, e => e is AbbProtocolException);
        AssertBothOutcomes(counts);
    }

    [Fact]
    public async Task AbbMessageReader_EndlessStreamWithoutTerminator_FailsAtItsBound()
    {
        var reader = new AbbMessageReader();
        var chunk = Encoding.ASCII.GetBytes("$24 1 2 3 4 5 6 7>");
        long fed = 0;
        var error = await Assert.ThrowsAsync<AbbProtocolException>(() => Fuzz.RunBoundedAsync(() =>
        {
            for (int i = 0; i < 1_000_000; i++)
            {
                reader.Append(chunk);
                fed += chunk.Length;
                reader.TryRead(out _);
            }
        }));
        Assert.InRange(fed, AbbMessageReader.MaxMessageLength, AbbMessageReader.MaxMessageLength + chunk.Length);
        Assert.StartsWith("$24 1 2 3", error.ReceivedText, StringComparison.Ordinal);
    }

    [Fact]
    public async Task KukaXmlReader_RandomAndMutatedXml_ElementsOrKukaProtocolException()
    {
        var counts = await RunAsync(14_004, KukaXml, XmlAlphabet, 160, () => new KukaXmlReader(), (reader, bytes) =>
        {
            reader.Append(bytes);
            int read = 0;
            while (true)
            {
                int before = reader.PendingByteCount;
                if (!reader.TryRead(out KukaElement element))
                {
                    return read;
                }
                Assert.True(reader.PendingByteCount < before, "a read consumes bytes");
                read++;
                // What each side makes of an element: the host reads states and poses, the virtual controller actions.
                TryDecode(() => KukaState.Parse(element));
                TryDecode(() => KukaMessages.ReadPose(element));
                TryDecode(() => KukaInstruction.Parse(element));
            }
        }, e => e is KukaProtocolException);
        AssertBothOutcomes(counts);
    }

    [Fact]
    public async Task KukaXmlReader_EndlessElement_FailsAtItsBound()
    {
        var reader = new KukaXmlReader();
        // About 1 KB a read: the reader parses its pending bytes again on every read, so tiny reads would make this test
        // quadratic (minutes on a loaded debug build) without testing anything more.
        var chunk = Encoding.ASCII.GetBytes(string.Concat(Enumerable.Repeat(" A=\"1\" B=\"2\" C=\"3\"", 50)));
        reader.Append("<S"u8);
        long fed = 2;
        await Assert.ThrowsAsync<KukaProtocolException>(() => Fuzz.RunBoundedAsync(() =>
        {
            for (int i = 0; i < 1_000_000; i++)
            {
                reader.Append(chunk);
                fed += chunk.Length;
                reader.TryRead(out _);
            }
        }));
        Assert.InRange(fed, KukaXmlReader.MaxElementLength, KukaXmlReader.MaxElementLength + chunk.Length);
    }

    [Fact]
    public async Task RtdeReader_RandomPackages_PackagesOrConnectionError()
    {
        var random = new Random(14_005);
        int packages = 0, refused = 0, samples = 0, corrupt = 0;
        await Fuzz.RunBoundedAsync(() =>
        {
            for (int i = 0; i < Fuzz.Cases; i++)
            {
                var reader = new RtdePackageReader();
                // Every other case is a data package of the recipe's size (UrDriver.PackageLength bytes of payload) with random contents.
                var bytes = new byte[i % 2 == 1 ? UrDriver.PackageLength + 3 : random.Next(3, 200)];
                random.NextBytes(bytes);
                if (i % 2 == 1)
                {
                    System.Buffers.Binary.BinaryPrimitives.WriteUInt16BigEndian(bytes, (ushort)(i % 10 == 1 ? random.Next(0, 256) : bytes.Length));
                    bytes[2] = Rtde.DataPackage;
                    if (i % 4 == 1)
                    {
                        // Plausible doubles (small exponents) so that decoding goes all the way through.
                        for (int k = 12; k < 108; k += 8)
                        {
                            System.Buffers.Binary.BinaryPrimitives.WriteDoubleBigEndian(bytes.AsSpan(k), (random.NextDouble() - 0.5) * 20);
                        }
                    }
                }
                try
                {
                    reader.Append(bytes);
                    while (reader.TryRead(out byte type, out ReadOnlySpan<byte> payload))
                    {
                        packages++;
                        if (type == Rtde.DataPackage && payload.Length == UrDriver.PackageLength)
                        {
                            try
                            {
                                var sample = UrDriver.Decode(payload);
                                Assert.True(double.IsFinite(sample.Position.X) && double.IsFinite(sample.Joints.J1));
                                samples++;
                            }
                            catch (RobotConnectionException)
                            {
                                corrupt++;
                            }
                        }
                    }
                }
                catch (RobotConnectionException)
                {
                    refused++;
                }
            }
        });
        Assert.InRange(packages, Fuzz.Cases / 4, Fuzz.Cases);
        Assert.InRange(refused, 100, Fuzz.Cases);
        Assert.InRange(samples, Fuzz.Cases / 10, Fuzz.Cases);
        Assert.InRange(corrupt, Fuzz.Cases / 10, Fuzz.Cases);
    }

    private static void TryDecode(Action decode)
    {
        try
        {
            decode();
        }
        catch (KukaProtocolException)
        {
        }
    }

    private static void AssertBothOutcomes((int Accepted, int Refused) counts)
    {
        Assert.Equal(Fuzz.Cases, counts.Accepted + counts.Refused);
        Assert.InRange(counts.Accepted, Fuzz.Cases / 50, Fuzz.Cases);
        Assert.InRange(counts.Refused, Fuzz.Cases / 50, Fuzz.Cases);
    }

    /// <summary>
    /// Feeds every case to a fresh decoder whole, and cut in two at a random point; counts cases that decoded at least one
    /// message (accepted) and those that failed with an allowed error (refused). Any other exception fails the test.
    /// </summary>
    private static async Task<(int Accepted, int Refused)> RunAsync<T>(
        int seed, string[] valid, byte[] alphabet, int maxLength, Func<T> create, Func<T, byte[], int> feed, Func<Exception, bool> allowed)
    {
        var random = new Random(seed);
        int accepted = 0, refused = 0;
        await Fuzz.RunBoundedAsync(() =>
        {
            for (int i = 0; i < Fuzz.Cases; i++)
            {
                byte[] bytes = Fuzz.Case(random, i, valid, alphabet, maxLength);
                int cut = random.Next(bytes.Length + 1);
                try
                {
                    T decoder = create();
                    int whole = feed(decoder, bytes);
                    T split = create();
                    int pieces = feed(split, bytes[..cut]) + feed(split, bytes[cut..]);
                    Assert.True(whole == pieces || typeof(T) == typeof(int), $"case {i}: {whole} messages whole, {pieces} when cut at {cut}");
                    if (whole > 0)
                    {
                        accepted++;
                    }
                    else
                    {
                        refused++;
                    }
                }
                catch (Exception e) when (allowed(e))
                {
                    refused++;
                }
            }
        });
        return (accepted, refused);
    }
}
