namespace Machina.Tests.Actions;

/// <summary>The descriptions written as ASCII bytes (<see cref="RobotAction.TryWriteDescriptionAscii"/>) are the characters' text.</summary>
public class DescriptionAsciiTests
{
    private static readonly double[] Numbers =
        [0, -0.0, 1, -1, 7.216, -0.954, 0.0005, 0.00049, 1e-5, 0.1 + 0.2, 1.0 / 3, 12.3456, 299.9995, 1234567.891, -98765432109.5, 1e13, 1e14, 3e15, 1e20];

    [Fact]
    public void Translations_TheSameTextAsTheCharacters_OrRefusedWhereANumberTakesTheGeneralText()
    {
        var random = new Random(49);
        int written = 0;
        for (int i = 0; i < 4_000; i++)
        {
            var move = new ActionTranslation(new Vector(Pick(random), Pick(random), Pick(random)), relative: random.Next(2) == 0);
            written += AssertSameOrRefused(move) ? 1 : 0;
        }
        Assert.InRange(written, 1_000, 4_000);
    }

    [Fact]
    public void RelativeRotations_TheSameTextAsTheCharacters_OrRefusedWhereANumberTakesTheGeneralText()
    {
        var random = new Random(50);
        int written = 0;
        for (int i = 0; i < 4_000; i++)
        {
            Vector axis = random.Next(3) switch
            {
                0 => new Vector(0, 0, random.Next(2) == 0 ? 1 : -1),
                1 => new Vector(random.Next(-1, 2), random.Next(-1, 2), 1),
                _ => new Vector(random.NextDouble() - 0.5, random.NextDouble(), 0.25),
            };
            written += AssertSameOrRefused(new ActionRotation(axis, Pick(random), relative: true)) ? 1 : 0;
        }
        Assert.InRange(written, 1_000, 4_000);
    }

    [Fact]
    public void OtherActions_WriteNoBytes()
    {
        byte[] buffer = new byte[RobotAction.MaxWrittenDescriptionChars];
        Assert.Equal(-1, new ActionRotation(Rotation.FlippedAroundY, false).TryWriteDescriptionAscii(buffer));
        Assert.Equal(-1, new ActionWait(5).TryWriteDescriptionAscii(buffer));
        Assert.Equal(-1, new ActionRotation(new Vector(0, 0, 1), 1e-5, true).TryWriteDescriptionAscii(buffer)); // 1E-05
        Assert.Equal(-1, new ActionTranslation(new Vector(1e20, 0, 0), true).TryWriteDescriptionAscii(buffer));
        int length = new ActionRotation(new Vector(0, -2, 0), -0.954, true).TryWriteDescriptionAscii(buffer);
        Assert.Equal("Rotate -0.954 deg around [0, -1, 0]", System.Text.Encoding.ASCII.GetString(buffer, 0, length));
    }

    [Fact]
    public void AsciiNarrow_TryWriteDescription_BytesOrTheNarrowedCharacters()
    {
        byte[] line = new byte[8 + RobotAction.MaxWrittenDescriptionChars + 1];
        char[] scratch = new char[RobotAction.MaxWrittenDescriptionChars];
        // A turn by 1E-05 degrees is written as characters only (E notation), and narrowed.
        var tiny = new ActionRotation(new Vector(0, 0, 1), 1e-5, true);
        int at = AsciiNarrow.TryWriteDescription(line, 2, "; ["u8, tiny, scratch);
        Assert.Equal("; [" + tiny.Describe() + "]", System.Text.Encoding.ASCII.GetString(line, 2, at - 2));
        var move = new ActionTranslation(new Vector(1, -2.5, 3), false);
        at = AsciiNarrow.TryWriteDescription(line, 0, default, move, scratch);
        Assert.Equal("Move to [1, -2.5, 3] mm]", System.Text.Encoding.ASCII.GetString(line, 0, at));
        Assert.Equal(-1, AsciiNarrow.TryWriteDescription(line, 0, default, new ActionWait(5), scratch));
    }

    private static double Pick(Random random) => random.Next(3) == 0 ? Numbers[random.Next(Numbers.Length)] * (random.Next(2) == 0 ? 1 : -1)
                                                 : random.Next(-999_999, 999_999) / 1000.0;

    private static bool AssertSameOrRefused(RobotAction action)
    {
        char[] chars = new char[RobotAction.MaxWrittenDescriptionChars];
        byte[] bytes = new byte[RobotAction.MaxWrittenDescriptionChars];
        string text = new(chars, 0, action.TryWriteDescription(chars));
        Assert.Equal(action.Describe(), text);
        int written = action.TryWriteDescriptionAscii(bytes);
        // Left to the characters exactly where a number takes .NET's general text: a coordinate too large for the fast digits,
        // an angle that is not its shortest few decimals.
        bool general = action switch
        {
            ActionTranslation move => !(NumAppend.TryScale(move.Translation.X, 3, out _) && NumAppend.TryScale(move.Translation.Y, 3, out _)
                                        && NumAppend.TryScale(move.Translation.Z, 3, out _)),
            ActionRotation turn => NumShortest.TryWrite(new char[NumAppend.MaxChars], turn.Request.Angle) < 0,
            _ => true,
        };
        Assert.Equal(general, written < 0);
        if (written < 0)
        {
            return false;
        }
        Assert.Equal(text, System.Text.Encoding.ASCII.GetString(bytes, 0, written));
        return true;
    }
}
