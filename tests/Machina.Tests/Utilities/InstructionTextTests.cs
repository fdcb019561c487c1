using System.Text;

namespace Machina.Tests.Utilities;

/// <summary>The instruction text written straight into a builder is the text of <c>ToInstruction()</c>, character for character.</summary>
public class InstructionTextTests
{
    [Theory]
    [InlineData(1.5, -2, 0.25, "Move(1.5,-2,0.25);")]
    [InlineData(0, 0, 0, "Move(0,0,0);")]
    [InlineData(1e-7, 123456789.125, -0.1, "Move(1E-07,123456789.125,-0.1);")]
    public void AppendCall_Values_TextOfCall(double x, double y, double z, string expected)
    {
        var sb = new StringBuilder("# ");

        sb.AppendCall("Move", x, y, z);

        Assert.Equal("# " + expected, sb.ToString());
        Assert.Equal(expected, InstructionText.Call("Move", x, y, z));
    }

    [Fact]
    public void AppendInstruction_ManyMoves_SameAsToInstruction()
    {
        var random = new Random(25);
        var sb = new StringBuilder();
        for (int i = 0; i < 20_000; i++)
        {
            double Next() => Math.Round((random.NextDouble() - 0.5) * Math.Pow(10, random.Next(-6, 9)), random.Next(0, 12));
            var move = new ActionTranslation(new Vector(Next(), Next(), Next()), i % 2 == 0);

            move.AppendInstruction(sb.Clear());

            Assert.Equal(move.ToInstruction(), sb.ToString());
        }
    }
}
