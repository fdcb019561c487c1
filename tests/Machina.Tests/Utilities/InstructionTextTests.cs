namespace Machina.Tests.Utilities;

/// <summary>The instruction text written straight into a line is the text of <c>ToInstruction()</c>, character for character.</summary>
public class InstructionTextTests
{
    [Theory]
    [InlineData(1.5, -2, 0.25, "Move(1.5,-2,0.25);")]
    [InlineData(0, 0, 0, "Move(0,0,0);")]
    [InlineData(1e-7, 123456789.125, -0.1, "Move(1E-07,123456789.125,-0.1);")]
    [InlineData(double.MinValue, -double.Epsilon, double.MinValue, "Move(-1.7976931348623157E+308,-5E-324,-1.7976931348623157E+308);")]
    public void WriteCall_Values_TextOfCall(double x, double y, double z, string expected)
    {
        Span<char> line = stackalloc char[ActionTranslation.MaxInstructionChars + 2];
        "# ".CopyTo(line);

        int written = InstructionText.WriteCall(line[2..], "Move", x, y, z);

        Assert.Equal("# " + expected, new string(line[..(2 + written)]));
        Assert.Equal(expected, InstructionText.Call("Move", x, y, z));
    }

    [Fact]
    public void WriteInstruction_ManyMoves_SameAsToInstruction()
    {
        var random = new Random(25);
        var line = new char[ActionTranslation.MaxInstructionChars];
        for (int i = 0; i < 20_000; i++)
        {
            double Next() => Math.Round((random.NextDouble() - 0.5) * Math.Pow(10, random.Next(-6, 9)), random.Next(0, 12));
            var move = new ActionTranslation(new Vector(Next(), Next(), Next()), i % 2 == 0);

            int written = move.WriteInstruction(line);

            Assert.Equal(move.ToInstruction(), new string(line, 0, written));
        }
    }
}
