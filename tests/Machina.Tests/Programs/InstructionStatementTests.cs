namespace Machina.Tests.Programs;

/// <summary>InstructionStatement.ReadAll: each action of a text with the line and column of its statement (public since the tool uses it).</summary>
public sealed class InstructionStatementTests
{
    [Fact]
    public void ReadAll_GivesEachActionWithTheLineAndColumnOfItsStatement()
    {
        using var text = new StringReader("MoveTo(300, 0, 500);\n// a comment\n   Wait(250); Speed(10);\n");

        InstructionStatement[] statements = [.. InstructionStatement.ReadAll(text)];

        Assert.Equal(["MoveTo(300,0,500);", "Wait(250);", "Speed(10);"], statements.Select(s => s.Action.ToInstruction()));
        Assert.Equal([(1, 1), (3, 4), (3, 15)], statements.Select(s => (s.Line, s.Column)));
        Assert.All(statements, s => Assert.Equal(-1, s.Action.Id));   // not issued yet
    }

    [Fact]
    public void ReadAll_AMalformedStatement_ThrowsWithItsPlace_AfterTheGoodOnesBeforeIt()
    {
        using var text = new StringReader("MoveTo(300, 0, 500);\nMoov(10, 0, 0);\n");
        var read = new List<InstructionStatement>();

        var error = Assert.Throws<InstructionParseException>(() =>
        {
            foreach (InstructionStatement statement in InstructionStatement.ReadAll(text))
            {
                read.Add(statement);
            }
        });

        Assert.Single(read);
        Assert.Equal((2, 1), (error.Line, error.Column));
        Assert.Contains("did you mean", error.Problem, StringComparison.OrdinalIgnoreCase);
    }
}
