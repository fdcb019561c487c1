namespace Machina.Tests.Programs;

/// <summary>A mistyped instruction gets "did you mean", as a mistyped command of the machina tool does.</summary>
public sealed class InstructionSuggestionTests
{
    [Fact]
    public void Do_MistypedInstruction_SuggestsTheClosestName()
    {
        var bot = Robot.Create("Typo", "ABB");

        var ex = Assert.Throws<InstructionParseException>(() => bot.Do("MoveTo(400, 0, 500);\nMoov(10, 0, 0);"));

        Assert.Equal((2, 1), (ex.Line, ex.Column));
        Assert.Equal("unknown instruction \"Moov\"; did you mean \"Move\"?", ex.Problem);
        Assert.Equal("Line 2, column 1: unknown instruction \"Moov\"; did you mean \"Move\"?", ex.Message);
        Assert.Null(bot.GetCurrentPosition());
    }

    [Theory]
    [InlineData("Rotat(0,0,1,90);", "unknown instruction \"Rotat\"; did you mean \"Rotate\"?")]
    [InlineData("SpedTo(100);", "unknown instruction \"SpedTo\"; did you mean \"SpeedTo\"?")]
    [InlineData("Wiat(100);", "unknown instruction \"Wiat\"; did you mean \"Wait\"?")]
    [InlineData("AxisTo(0,0,0,0,90,0);", "unknown instruction \"AxisTo\"; did you mean \"AxesTo\"?")]
    [InlineData("Speeds(10);", "unknown instruction \"Speeds\"; did you mean \"Speed\"?")]
    [InlineData("Fly(1);", "unknown instruction \"Fly\".")]
    [InlineData("RotationSpeed(1);", "unknown instruction \"RotationSpeed\".")]
    public void Parse_UnknownName_SuggestsOnlyCloseNames(string text, string problem)
    {
        var ex = Assert.Throws<InstructionParseException>(() => Instructions.Parse(text));

        Assert.Equal(problem, ex.Problem);
    }

    [Fact]
    public void Parse_EquallyCloseNames_AreAllSuggestedInOrder()
    {
        // "Mve" is one letter from "Move" only; "Axs" is one letter from "Axes" only; "MoveT" is one from "Move" and "MoveTo".
        var ex = Assert.Throws<InstructionParseException>(() => Instructions.Parse("MoveT(1,2,3);"));

        Assert.Equal("unknown instruction \"MoveT\"; did you mean \"Move\" or \"MoveTo\"?", ex.Problem);
    }
}
