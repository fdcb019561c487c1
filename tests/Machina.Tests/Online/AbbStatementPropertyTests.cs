using Machina.Simulation;

namespace Machina.Tests.Online;

/// <summary>
/// Issue 28: "can the driver run it" is one function (<see cref="AbbRequest.WhyStatementCannotBeSent"/>), used by the encoder and
/// by <see cref="AbbOnline.WhyCannotStream"/> at issue time. Seeded random custom statements: whatever is accepted encodes and is
/// read by the virtual driver as one request with that code; whatever is refused is refused by name, and never reaches the wire.
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
                Assert.True(AbbRequestParser.TryParse(wire.AsSpan(0, wire.Length - 1), out AbbRequest read, out string? error), $"{wire}: {error}");
                Assert.Equal(5, read.Id);
                Assert.Equal(double.Parse(statement.Trim().Split(' ', '\t')[0], Num.Inv), read.Code);
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
}
