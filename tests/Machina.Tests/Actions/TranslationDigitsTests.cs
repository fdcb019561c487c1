namespace Machina.Tests.Actions;

public class TranslationDigitsTests
{
    [Fact]
    public void BothTexts_AsTheMoveWritesThem_ForShortAndLongNumbers()
    {
        // Numbers whose texts agree (at most 3 decimals, read back exactly) and numbers where they differ (more decimals, tiny,
        // huge, −0): the kept digits must give exactly the move's own texts either way, asked in either order and repeatedly.
        double[] numbers = [0, -0.0, 7.216, -0.954, 0.001, -0.0005, 12.3456, 1e-5, 1234567.891, -98765432109.5, 1e13, 9.99e13, 1e14, 3e15, 0.1 + 0.2];
        var random = new Random(28);
        var moves = new List<ActionTranslation>();
        foreach (double x in numbers)
        {
            moves.Add(new ActionTranslation(new Vector(x, random.Next(-9999, 9999) / 1000.0, numbers[random.Next(numbers.Length)]), relative: random.Next(2) == 0));
        }
        for (int i = 0; i < 2_000; i++)
        {
            moves.Add(new ActionTranslation(new Vector(random.Next(-99999, 99999) / 1000.0, (random.NextDouble() - 0.5) * 20, random.Next(-500, 500) / 100.0), relative: true));
        }
        var digits = new TranslationDigits();
        char[] expected = new char[ActionTranslation.MaxInstructionChars + ActionTranslation.MaxDescriptionChars];
        char[] actual = new char[ActionTranslation.MaxInstructionChars + ActionTranslation.MaxDescriptionChars];
        for (int i = 0; i < moves.Count; i++)
        {
            ActionTranslation move = moves[i];
            bool instructionFirst = i % 2 == 0;
            for (int round = 0; round < 2; round++)
            {
                if (instructionFirst)
                {
                    AssertInstruction(move);
                    AssertDescription(move);
                }
                else
                {
                    AssertDescription(move);
                    AssertInstruction(move);
                }
            }
        }

        void AssertInstruction(ActionTranslation move)
        {
            string own = new(expected, 0, move.WriteInstruction(expected));
            Assert.Equal(move.ToInstruction(), own);
            Assert.Equal(own, new string(actual, 0, digits.WriteInstruction(move, actual)));
        }

        void AssertDescription(ActionTranslation move)
        {
            Assert.Equal(move.Describe(), new string(actual, 0, digits.WriteDescription(move, actual)));
        }
    }

    [Fact]
    public void ShortNumbers_OneTextForBoth()
    {
        var digits = new TranslationDigits();
        var move = new ActionTranslation(new Vector(7.216, -0.954, 0), relative: true);
        Span<char> buffer = stackalloc char[ActionTranslation.MaxDescriptionChars];
        Assert.Equal("Move(7.216,-0.954,0);", new string(buffer[..digits.WriteInstruction(move, buffer)]));
        Assert.Equal("Move [7.216, -0.954, 0] mm", new string(buffer[..digits.WriteDescription(move, buffer)]));
        var to = new ActionTranslation(new Vector(300, 0.5, 12.3456), relative: false);
        Assert.Equal("MoveTo(300,0.5,12.3456);", new string(buffer[..digits.WriteInstruction(to, buffer)]));
        Assert.Equal("Move to [300, 0.5, 12.346] mm", new string(buffer[..digits.WriteDescription(to, buffer)]));
    }
}
