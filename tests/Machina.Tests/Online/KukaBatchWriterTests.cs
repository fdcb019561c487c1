using System.Text;

namespace Machina.Tests.Online;

/// <summary>
/// The host's batch of one action written without a builder (<see cref="KukaInstruction.TryWriteBatch"/>): the same characters as
/// the builder's <see cref="KukaInstruction.AppendBatch(StringBuilder, in KukaInstruction)"/>, byte for byte (docs/protocol-kuka.md).
/// </summary>
public class KukaBatchWriterTests
{
    private static string Built(in KukaInstruction instruction)
    {
        var sb = new StringBuilder();
        KukaInstruction.AppendBatch(sb, instruction);
        return sb.ToString();
    }

    private static string? Written(in KukaInstruction instruction)
    {
        Span<char> plain = stackalloc char[KukaInstruction.MaxPlainBatchChars];
        int length = instruction.TryWriteBatch(plain);
        return length < 0 ? null : new string(plain[..length]);
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
    public void TryWriteBatch_PlainAction_SameCharactersAsTheBuilder(int id, int code, double[] parameters)
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
    public void TryWriteBatch_TextOrHugeValue_LeftToTheBuilder()
    {
        var values = new KukaValues();
        values[0] = 1e20;

        Assert.Null(Written(new KukaInstruction(1, KukaActionCode.Message, new KukaValues(), "hi")));
        Assert.Null(Written(new KukaInstruction(2, KukaActionCode.Wait, values, "")));
        Assert.Contains("V1=\"100000000000000000000\"", Built(new KukaInstruction(2, KukaActionCode.Wait, values, "")));
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
