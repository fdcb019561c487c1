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
            // Every other move has a long number (its texts differ), the others only numbers of at most 3 decimals.
            double y = i % 2 == 0 ? (random.NextDouble() - 0.5) * 20 : random.Next(-9999, 9999) / 1000.0;
            moves.Add(new ActionTranslation(new Vector(random.Next(-99999, 99999) / 1000.0, y, random.Next(-500, 500) / 100.0), relative: true));
        }
        var digits = new TranslationDigits();
        char[] expected = new char[ActionTranslation.MaxInstructionChars + ActionTranslation.MaxDescriptionChars];
        byte[] actual = new byte[ActionTranslation.MaxInstructionChars + ActionTranslation.MaxDescriptionChars];
        int shared = 0;
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
        // Half of the random moves have numbers of at most 3 decimals: their digits are shared (four texts each).
        Assert.InRange(shared, 4 * 1_000, 4 * (1_000 + numbers.Length));

        void AssertInstruction(ActionTranslation move)
        {
            string own = new(expected, 0, move.WriteInstruction(expected));
            Assert.Equal(move.ToInstruction(), own);
            AssertSharedOrRefused(move, own, digits.TryWriteInstructionAscii(move, actual));
        }

        void AssertDescription(ActionTranslation move)
        {
            AssertSharedOrRefused(move, move.Describe(), digits.TryWriteDescriptionAscii(move, actual));
        }

        void AssertSharedOrRefused(ActionTranslation move, string own, int written)
        {
            Vector v = move.Translation;
            bool readsBack = NumShortest.TryThousandths(Math.Abs(v.X), out _) && NumShortest.TryThousandths(Math.Abs(v.Y), out _)
                             && NumShortest.TryThousandths(Math.Abs(v.Z), out _);
            // Refused exactly where the two texts may differ: a number that does not read back from 3 decimals.
            Assert.Equal(readsBack, written >= 0);
            if (written < 0)
            {
                return;
            }
            shared++;
            Assert.Equal(own, System.Text.Encoding.ASCII.GetString(actual, 0, written));
        }
    }

    [Fact]
    public void Refused_ExactlyWhenANumberNeedsMoreThanThreeDecimals()
    {
        var digits = new TranslationDigits();
        byte[] buffer = new byte[ActionTranslation.MaxInstructionChars];
        Assert.Equal(-1, digits.TryWriteInstructionAscii(new ActionTranslation(new Vector(1, 2.0005, 3), relative: true), buffer));
        Assert.Equal(-1, digits.TryWriteDescriptionAscii(new ActionTranslation(new Vector(1e-5, 2, 3), relative: true), buffer));
        Assert.Equal(-1, digits.TryWriteDescriptionAscii(new ActionTranslation(new Vector(0.1 + 0.2, 2, 3), relative: false), buffer));
        Assert.True(digits.TryWriteDescriptionAscii(new ActionTranslation(new Vector(1, 2.005, -0.0), relative: false), buffer) > 0);
    }

    [Fact]
    public void ShortNumbers_OneTextForBoth()
    {
        var digits = new TranslationDigits();
        var move = new ActionTranslation(new Vector(7.216, -0.954, 0), relative: true);
        byte[] buffer = new byte[ActionTranslation.MaxDescriptionChars + ActionTranslation.MaxInstructionChars];
        Assert.Equal("Move(7.216,-0.954,0);", Text(digits.TryWriteInstructionAscii(move, buffer)));
        Assert.Equal("Move [7.216, -0.954, 0] mm", Text(digits.TryWriteDescriptionAscii(move, buffer)));
        var to = new ActionTranslation(new Vector(300, 0.5, -12.345), relative: false);
        Assert.Equal("MoveTo(300,0.5,-12.345);", Text(digits.TryWriteInstructionAscii(to, buffer)));
        Assert.Equal("Move to [300, 0.5, -12.345] mm", Text(digits.TryWriteDescriptionAscii(to, buffer)));

        string Text(int length) => System.Text.Encoding.ASCII.GetString(buffer, 0, length);
    }
}
