namespace Machina.Tests.Core;

/// <summary>Instruction text at odd places: comments between arguments, escapes that are not quite escapes.</summary>
public class InstructionTextEdgeTests
{
    private static string Texts(string text) => string.Join(" ", Instructions.Parse(text).Select(a => a.ToInstruction()));

    [Fact]
    public void CommentsBetweenArguments_AreSkipped()
    {
        Assert.Equal("MoveTo(1,2,3);", Texts("MoveTo(1, // x\n  2, // y\r\n  3 // z\n);"));
        Assert.Equal("MoveTo(1,2,3); Wait(5);", Texts("MoveTo( // where to\n1,2,3); Wait(5 // ms\n)"));
    }

    [Fact]
    public void DoubleSlashInsideABareWord_IsText()
    {
        Assert.Equal("Message(\"http://host/a\");", Texts("Message(http://host/a)"));
        Assert.Equal("Message(\"a//b\");", Texts("Message(\"a//b\") // note"));
    }

    [Fact]
    public void CommentSwallowingTheClosingParenthesis_IsReportedWhereTheTextEnds()
    {
        var ex = Assert.Throws<InstructionParseException>(() => Instructions.Parse("MoveTo(1, 2, 3 // )"));

        Assert.Equal(1, ex.Line);
        Assert.Equal(20, ex.Column);
        Assert.Equal("MoveTo( is not closed with ')'.", ex.Problem);
    }

    [Fact]
    public void UnicodeEscapeWithSpaces_IsKeptAsWritten()
    {
        var message = (ActionMessage)Assert.Single(Instructions.Parse("Message(\"\\u 41 !\")"));

        Assert.Equal("\\u 41 !", message.Message);
        Assert.Equal("A", ((ActionMessage)Instructions.Parse("Message(\"\\u0041\")")[0]).Message);
    }
}

/// <summary>Argument checks of the Instructions entry points happen at the call.</summary>
public class InstructionsArgumentTests
{
    [Fact]
    public void Enumerate_NullText_ThrowsAtTheCall()
    {
        var ex = Assert.Throws<ArgumentNullException>(() => Instructions.Enumerate(null!));

        Assert.Equal("text", ex.ParamName);
        Assert.Throws<ArgumentNullException>(() => Instructions.Parse(null!));
    }

    [Fact]
    public void Enumerate_Twice_ReadsTheWholeTextEachTime()
    {
        IEnumerable<RobotAction> actions = Instructions.Enumerate("Wait(1); Wait(2);");

        Assert.Equal(2, actions.Count());
        Assert.Equal(["Wait(1);", "Wait(2);"], actions.Select(a => a.ToInstruction()));
    }
}
