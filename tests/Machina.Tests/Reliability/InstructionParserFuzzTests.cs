using System.Text;

namespace Machina.Tests.Reliability;

public class InstructionParserFuzzTests
{
    private static readonly string[] Valid =
    [
        "MoveTo(400, 300, 500);", "Move(0,0,-10); Rotate(1,0,0,90);", "Axes(0,0,0,0,90,0);", "Speed(100);",
        "WriteDigital(\"DO_1\", true);", "WriteAnalog(2, 0.5, false);", "Message(\"Hello; \\\"world\\\"\");",
        "Wait(1000); // comment\nPrecision(5);", "TransformTo(400, 0, 500, -1, 0, 0, 0, 1, 0);", "CustomCode(\"a;\", true);",
        "AttachTool(\"tool\"); DefineTool(\"t\", 0,0,100, 1,0,0, 0,1,0, 1, 0,0,50);", "ArcMotion(1,2,3,4,5,6);",
        "ExternalAxis(1, 100, \"All\");", "Temperature(200, \"extruder\", true, false);", "PushSettings(); PopSettings();",
    ];

    private static readonly byte[] Alphabet = Encoding.ASCII.GetBytes("MoveToAxesSpeedWaitMessage(),;\"\\ -+.eE0123456789/\n\ttruefalse_");

    [Fact]
    public async Task Parse_RandomAndMutatedText_ReturnsActionsOrThrowsInstructionParseException()
    {
        var random = new Random(14_001);
        int parsed = 0, refused = 0;
        await Fuzz.RunBoundedAsync(() =>
        {
            for (int i = 0; i < Fuzz.Cases; i++)
            {
                string text = Encoding.UTF8.GetString(Fuzz.Case(random, i, Valid, Alphabet, 80));
                try
                {
                    var actions = Instructions.Parse(text);
                    Assert.All(actions, a => Assert.NotNull(a.ToInstruction()));
                    parsed++;
                }
                catch (InstructionParseException e)
                {
                    Assert.False(string.IsNullOrWhiteSpace(e.Message), $"empty message for \"{text}\"");
                    refused++;
                }
            }
        });
        Assert.Equal(Fuzz.Cases, parsed + refused);
        Assert.InRange(parsed, Fuzz.Cases / 50, Fuzz.Cases); // the mutations keep enough valid programs to reach deep
        Assert.InRange(refused, Fuzz.Cases / 4, Fuzz.Cases);
    }

    [Fact]
    public async Task Parse_HugeInputs_FinishWithoutBlowingUp()
    {
        string[] huge =
        [
            new string('(', 200_000), "Move(" + new string('1', 200_000) + ",0,0);", "\"" + new string('a', 200_000),
            string.Concat(Enumerable.Repeat("Speed(1);", 20_000)), "//" + new string('x', 200_000),
        ];
        var outcomes = new List<string>();
        await Fuzz.RunBoundedAsync(() =>
        {
            foreach (string text in huge)
            {
                try
                {
                    outcomes.Add($"{Instructions.Parse(text).Count} actions");
                }
                catch (InstructionParseException)
                {
                    outcomes.Add("refused");
                }
            }
        });
        Assert.Equal(["refused", "refused", "refused", "20000 actions", "0 actions"], outcomes);
    }
}
