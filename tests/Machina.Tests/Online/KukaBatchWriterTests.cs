using System.Text;

namespace Machina.Tests.Online;

/// <summary>
/// The host's batch of one action written on the stack (<see cref="KukaInstruction.WriteBatch(Span{char})"/>), going on in a builder
/// when it does not fit: the same characters as the builder's <see cref="KukaInstruction.AppendBatch(StringBuilder, in KukaInstruction)"/>,
/// byte for byte (docs/protocol-kuka.md).
/// </summary>
public class KukaBatchWriterTests
{
    private static string Built(in KukaInstruction instruction)
    {
        var sb = new StringBuilder();
        KukaInstruction.AppendBatch(sb, instruction);
        return sb.ToString();
    }

    /// <summary>The batch written on the stack, or null when it went on in a builder.</summary>
    private static string? Written(in KukaInstruction instruction)
    {
        KukaText text = instruction.WriteBatch(stackalloc char[KukaInstruction.StackBatchChars]);
        return text.Builder is null ? new string(text.Written) : null;
    }

    /// <summary>The batch as the host sends it, whichever way it was written.</summary>
    private static string Sent(in KukaInstruction instruction)
    {
        KukaText text = instruction.WriteBatch(stackalloc char[KukaInstruction.StackBatchChars]);
        return text.Builder?.ToString() ?? new string(text.Written);
    }

    public static TheoryData<int, int, double[]> Actions => new()
    {
        { 1, 1, [400, 0, 500, 180, 0, 180, 0] },
        { 2_147_483_647, 2, [-0.0, -0.0000004, 0.0000005, 0.0000015, -123.4567891, 999999.999999, 1e-7] },
        { 42, 17, [1, 2, 3, 4, 5, 6, 0, -7.25, 8.5, 9.125, 10.0625, 11, 12] },
        { 7, 4, [0.2, 0, 0, 0, 0, 0, 0] },
        { 8, 13, [123456789.123456, -987654321.5, 5, 0, 0, 0, 0] },
    };

    [Theory]
    [MemberData(nameof(Actions))]
    public void WriteBatch_PlainAction_SameCharactersAsTheBuilder(int id, int code, double[] parameters)
    {
        var values = new KukaValues();
        for (int i = 0; i < parameters.Length; i++)
        {
            values[i] = parameters[i];
        }
        var instruction = new KukaInstruction(id, (KukaActionCode)code, values, "");

        string? written = Written(instruction);

        Assert.NotNull(written);
        Assert.Equal(Built(instruction), written);
        Assert.StartsWith($"<DT><DR><A ID=\"{id}\" T=\"{code}\" V1=\"", written);
        Assert.EndsWith(" M=\"\"/></DR></DT>", written);
    }

    [Fact]
    public void WriteBatch_ShortMessage_OnTheStackEscapedAsTheBuilder()
    {
        var instruction = new KukaInstruction(1, KukaActionCode.Message, new KukaValues(), "a<b & \"c\" 'd' >\u0007\u00e9");

        string? written = Written(instruction);

        Assert.NotNull(written);
        Assert.Equal(Built(instruction), written);
        Assert.EndsWith(" M=\"a&lt;b &amp; &quot;c&quot; &apos;d&apos; &gt; ?\"/></DR></DT>", written);
    }

    [Fact]
    public void WriteBatch_HugeValueOrLongText_GoesOnInTheBuilder()
    {
        var huge = new KukaValues();
        huge[0] = 1e20;
        var lastHuge = new KukaValues();
        for (int i = 0; i < KukaProtocol.CircularValueCount; i++)
        {
            lastHuge[i] = i + 0.5;
        }
        lastHuge[12] = -3e9;
        KukaInstruction[] spilled =
        [
            new(2, KukaActionCode.Wait, huge, ""),
            new(3, KukaActionCode.Circular, lastHuge, ""),
            new(4, KukaActionCode.Message, new KukaValues(), new string('"', 300)),
        ];

        foreach (KukaInstruction instruction in spilled)
        {
            Assert.Null(Written(instruction));
            Assert.Equal(Built(instruction), Sent(instruction));
        }
        Assert.Contains("V1=\"100000000000000000000\"", Sent(spilled[0]));
        Assert.Contains(" V12=\"11.5\" V13=\"-3000000000\" M=\"\"/>", Sent(spilled[1]));
        Assert.Equal(300 * "&quot;".Length, Sent(spilled[2]).Split("M=\"")[1].Split("\"/>")[0].Length);
    }

    [Fact]
    public void Encode_MoveAndMessage_ExactBytes()
    {
        var online = new KukaOnline();
        var cursor = new RobotCursor();
        var move = new ActionTransformation(new Vector(400, 0, 500), Rotation.FlippedAroundY, false, true) { Id = 3 };
        var message = new ActionMessage("a < b") { Id = 4 };
        Assert.Null(cursor.TryApply(move));
        ActionFrame moveFrame = online.Encode(move, cursor, out string? refusal);
        Assert.Null(cursor.TryApply(message));
        ActionFrame messageFrame = online.Encode(message, cursor, out _);

        Assert.Null(refusal);
        Assert.Equal("<DT><DR><A ID=\"3\" T=\"1\" V1=\"400\" V2=\"0\" V3=\"500\" V4=\"180\" V5=\"0\" V6=\"180\" V7=\"0\" M=\"\"/></DR></DT>",
            Encoding.ASCII.GetString(moveFrame.Bytes));
        Assert.Equal("<DT><DR><A ID=\"4\" T=\"8\" V1=\"0\" V2=\"0\" V3=\"0\" V4=\"0\" V5=\"0\" V6=\"0\" V7=\"0\" M=\"a &lt; b\"/></DR></DT>",
            Encoding.ASCII.GetString(messageFrame.Bytes));
    }
}
