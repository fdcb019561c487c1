namespace Machina.Tests.Programs;

/// <summary>Lines whose middle a writer keeps from line to line (<c>PackedLines.AddKept</c>): stored once, read back whole.</summary>
public class PackedLinesKeptTests
{
    private const string Middle = "], [0, 0, 1, 0], [0,0,0,0], [9E9,9E9,9E9,9E9,9E9,9E9]], vel100, z5, Tool0\\WObj:=WObj0;  ! [";

    private static (string Line, int KeptStart, int KeptLength) Move(int i, string middle = Middle, string note = "")
    {
        string head = "    MoveL [[" + (300 + i).ToString(System.Globalization.CultureInfo.InvariantCulture) + ", 0, 500";
        return (head + middle + "Move [" + i.ToString(System.Globalization.CultureInfo.InvariantCulture) + ", 0, 0] mm" + note + "]", head.Length, middle.Length);
    }

    private static string[] Fill(PackedLines packed, IEnumerable<(string Line, int KeptStart, int KeptLength)> lines)
    {
        var added = new List<string>();
        foreach ((string line, int start, int length) in lines)
        {
            if (length < 0)
            {
                packed.Add(line); // a plain line between kept ones
            }
            else
            {
                packed.AddKept(line, start, length);
            }
            added.Add(line);
        }
        return [.. added];
    }

    private static void AssertReadsBack(string[] expected, PackedLines packed)
    {
        Assert.Equal(expected.Length, packed.Count);
        Assert.Equal(expected, packed);
        Assert.Equal(expected.Sum(l => (long)l.Length), packed.CharacterCount);
        for (int i = 0; i < expected.Length; i += Math.Max(1, expected.Length / 50))
        {
            Assert.Equal(expected[i], packed[i]);
        }
        string joined = string.Concat(expected.Select(l => l + "\r\n"));
        var writer = new StringWriter();
        packed.WriteTo(writer, "\r\n");
        Assert.Equal(joined, writer.ToString());
        var copied = new char[joined.Length];
        packed.CopyTo(copied, "\r\n");
        Assert.Equal(joined, new string(copied));
        var twoThreads = new char[joined.Length];
        packed.CopyTo(twoThreads.AsMemory(), "\r\n");
        Assert.Equal(joined, new string(twoThreads));
    }

    [Fact]
    public void AddKept_SameMiddleEveryLine_StoredOnceAndReadBackWhole()
    {
        var packed = new PackedLines();
        string[] expected = Fill(packed, Enumerable.Range(0, 40_000).Select(i => Move(i)));

        AssertReadsBack(expected, packed);
        // The middle is stored with the first line only: every other line holds its own characters alone.
        Assert.Equal(packed.CharacterCount - (expected.Length - 1) * (long)Middle.Length, packed.StoredCharacters());
    }

    [Fact]
    public void AddKept_MiddleChangesAndPlainLinesBetween_EachLineReadsBackExactly()
    {
        var random = new Random(45);
        var lines = new List<(string, int, int)>();
        string middle = Middle;
        for (int i = 0; i < 12_000; i++)
        {
            int roll = random.Next(100);
            if (roll < 3)
            {
                middle = Middle.Replace("vel100", "vel" + random.Next(1000).ToString(System.Globalization.CultureInfo.InvariantCulture));
            }
            if (roll is >= 3 and < 6)
            {
                lines.Add(("    ! a plain line " + i.ToString(System.Globalization.CultureInfo.InvariantCulture), 0, -1));
            }
            else if (roll is >= 6 and < 8)
            {
                lines.Add(Move(i, middle, " é ✓")); // not ASCII after the middle: kept as characters, whole
            }
            else if (roll == 8)
            {
                lines.Add(Move(i, middle.Replace("z5", "zé"))); // not ASCII in the middle itself
            }
            else if (roll == 9)
            {
                (string line, int start, _) = Move(i, middle);
                lines.Add((line, start, 0)); // nothing kept
            }
            else
            {
                lines.Add(Move(i, middle));
            }
        }
        var packed = new PackedLines();
        string[] expected = Fill(packed, lines);

        AssertReadsBack(expected, packed);
        Assert.True(packed.StoredCharacters() < packed.CharacterCount / 2, $"{packed.StoredCharacters()} of {packed.CharacterCount} stored");
    }

    [Fact]
    public void AddKept_SameLengthMiddleThatDiffers_IsNotTakenForTheKeptOne()
    {
        var packed = new PackedLines();
        (string, int, int) first = Move(1), other = Move(2, Middle.Replace("z5", "z9"));
        string[] expected = Fill(packed, [first, other, Move(3), Move(4, Middle.Replace("z5", "z9"))]);

        AssertReadsBack(expected, packed);
        Assert.Contains("z9", packed[1], StringComparison.Ordinal);
        Assert.Contains("z5", packed[2], StringComparison.Ordinal);
        Assert.Equal(packed.CharacterCount, packed.StoredCharacters()); // each middle differed from the one before it
    }

    [Fact]
    public void AddKept_AfterAdoptedParts_KeepsEachPartsMiddles()
    {
        var spool = new PackedLines();
        string[] spooled = Fill(spool, Enumerable.Range(0, 3000).Select(i => Move(i)));
        var file = new PackedLines();
        string[] before = Fill(file, Enumerable.Range(5000, 100).Select(i => Move(i)));
        file.AppendAdopting(spool);
        string[] after = Fill(file, Enumerable.Range(9000, 100).Select(i => Move(i)));

        AssertReadsBack([.. before, .. spooled, .. after], file);
    }

    [Fact]
    public void Compile_RapidToolpathInMemory_StoresTheMovesKeptTextOnce()
    {
        var bot = Robot.Create("Kept", "ABB");
        bot.SpeedTo(100);
        bot.MoveTo(300, 0, 500);
        for (int i = 0; i < 2000; i++)
        {
            bot.Move(i % 2 == 0 ? 10 : -10, 0, 0.5);
        }
        RobotProgramFile mod = bot.Compile().Files.Single(f => f.Extension == "mod");
        var lines = Assert.IsType<PackedLines>(mod.Lines);
        string text = mod.ToText();

        Assert.Equal(string.Concat(lines.Select(l => l + "\r\n")), mod.ToText("\r\n"));
        Assert.Contains("    MoveL [[310, 0, 500.5], [0, 0, 1, 0], [0,0,0,0], [9E9,9E9,9E9,9E9,9E9,9E9]], vel100, z5, Tool0\\WObj:=WObj0;  ! [Move [10, 0, 0.5] mm]", text, StringComparison.Ordinal);
        Assert.True(lines.StoredCharacters() < lines.CharacterCount / 2, $"{lines.StoredCharacters()} of {lines.CharacterCount} stored");
    }
}
