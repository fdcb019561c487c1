using Machina.Simulation;

namespace Machina.Tests.Online;

/// <summary>
/// Issue 28: "can the driver run it" is one function (<see cref="AbbRequest.WhyStatementCannotBeSent"/>), used by the encoder and
/// by <see cref="AbbOnline.WhyCannotStream"/> at issue time. Seeded random custom statements: whatever is accepted encodes as one
/// request with that code (one ';' outside quoted text, as the driver splits them); whatever is refused is refused by name, and never
/// reaches the wire.
/// </summary>
public class AbbStatementPropertyTests
{
    private static readonly string[] Tokens =
    [
        "TPWrite", "x", "\"hi\"", "\"", "\"a b\"", "7", "1", "-3", "1.5", "+2", "1E39", "-1e-5", "3.4E38", "@2", "NaN", "Infinity",
        "0x10", "12", "100", "101", "103", "0.05", "9E9", new string('9', 90), "\"" + new string('q', 81) + "\"", "\t", "MoveL", "p10",
    ];

    [Fact]
    public void RandomCustomStatements_AcceptedOnesReadByTheDriverRefusedOnesNamed()
    {
        var random = new Random(28);
        var online = new AbbOnline();
        int accepted = 0, refused = 0;
        for (int n = 0; n < 3000; n++)
        {
            int count = random.Next(1, 15);
            string statement = string.Join(' ', Enumerable.Range(0, count).Select(_ => Tokens[random.Next(Tokens.Length)]));
            var action = new ActionCustomCode(statement, false);

            string? why = online.WhyCannotStream(action);

            if (why is null)
            {
                accepted++;
                string wire = AbbRequest.Custom(5, statement).ToWireText();
                // One request as the driver's ParseChunk splits them: "@5 code …;", a single ';' outside quoted text, at the end.
                Assert.StartsWith("@5 ", wire, StringComparison.Ordinal);
                Assert.Equal([wire.Length - 1], StatementEnds(wire));
                string code = wire[3..].Split(' ', '\t', ';')[0];
                Assert.Equal(double.Parse(statement.Trim().Split(' ', '\t')[0], Num.Inv), double.Parse(code, Num.Inv));
            }
            else
            {
                refused++;
                Assert.StartsWith("CustomCode (", why, StringComparison.Ordinal);
                Assert.Contains("cannot be streamed to an ABB robot: A custom ABB statement", why, StringComparison.Ordinal);
                Assert.Throws<ArgumentException>(() => AbbRequest.Custom(5, statement));
            }
        }
        Assert.True(accepted > 100 && refused > 100, $"accepted {accepted}, refused {refused}: the generator covers both sides");
    }

    /// <summary>Where a statement ends in <paramref name="wire"/>: each ';' outside a quoted text.</summary>
    private static List<int> StatementEnds(string wire)
    {
        var ends = new List<int>();
        bool inText = false;
        for (int i = 0; i < wire.Length; i++)
        {
            if (wire[i] == '"')
            {
                inText = !inText;
            }
            else if (wire[i] == ';' && !inText)
            {
                ends.Add(i);
            }
        }
        return ends;
    }
}
