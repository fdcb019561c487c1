namespace Machina.Tests.Programs;

public class PackedLinesTests
{
    private static List<string> SampleLines()
    {
        // Lengths from 0 to 300 characters, enough lines to fill several blocks (1 K, 2 K, 4 K … characters).
        var lines = new List<string>();
        for (int i = 0; i < 3000; i++)
        {
            lines.Add(i % 97 == 0 ? "" : new string((char)('a' + i % 26), i % 301) + i.ToString(System.Globalization.CultureInfo.InvariantCulture));
        }
        return lines;
    }

    [Fact]
    public void Add_ManyLinesAcrossBlocks_ReadsBackEachLineInOrder()
    {
        List<string> expected = SampleLines();
        var packed = new PackedLines();
        foreach (string line in expected)
        {
            packed.Add(line);
        }
        Assert.Equal(expected.Count, packed.Count);
        Assert.Equal(expected, packed);
        Assert.Equal(expected[1234], packed[1234]);
        Assert.Equal("", packed[0]);
        Assert.Equal(expected.Sum(l => (long)l.Length), packed.CharacterCount);
    }

    [Fact]
    public void Add_AsciiAndOtherLinesMixed_EachReadsBackExactly()
    {
        string[] expected = ["MoveL p1;", "unicodé ✓ 日本", "", "\u007f del", "🤖 robot", "plain", "\u0080 first non-ASCII", new string('z', 5000)];
        var packed = new PackedLines();
        foreach (string line in expected)
        {
            packed.Add(line);
        }
        var writer = new StringWriter();
        packed.WriteTo(writer, "\n");
        var copied = new char[packed.CharacterCount + expected.Length];
        packed.CopyTo(copied, "\n");

        Assert.Equal(expected, packed);
        Assert.Equal(expected[1], packed[1]);
        Assert.Equal(string.Concat(expected.Select(l => l + "\n")), writer.ToString());
        Assert.Equal(writer.ToString(), new string(copied));
    }

    [Fact]
    public void Add_LineLongerThanLargestBlock_IsKeptWhole()
    {
        var packed = new PackedLines();
        string huge = new('x', (1 << 20) + 5);
        packed.Add("before");
        packed.Add(huge);
        packed.Add("after");
        Assert.Equal(["before", huge, "after"], packed);
    }

    [Fact]
    public void WriteTo_AndCopyTo_GiveEachLineWithTheNewLine()
    {
        var packed = new PackedLines();
        packed.Add("MoveL p1;");
        packed.Add("");
        packed.Add("! done");
        var writer = new StringWriter();
        packed.WriteTo(writer, "\r\n");
        var text = new char[packed.CharacterCount + 3];
        packed.CopyTo(text, "\n");
        Assert.Equal("MoveL p1;\r\n\r\n! done\r\n", writer.ToString());
        Assert.Equal("MoveL p1;\n\n! done\n", new string(text));
    }

    [Fact]
    public void Compile_LongProgram_TextEqualsLinesJoined()
    {
        var bot = Robot.Create("Packed", "MACHINA");
        bot.MoveTo(300, 0, 500);
        for (int i = 0; i < 2000; i++)
        {
            bot.Move(i % 2 == 0 ? 1.5 : -1.5, 0, 0);
        }
        RobotProgramFile file = bot.Compile().Files[0];
        Assert.Equal(string.Concat(file.Lines.Select(l => l + "\n")), file.ToText());
        Assert.Equal("Move(-1.5,0,0);", file.Lines[^1]);
        Assert.Equal(file.Lines.Count, file.ToText().Count(c => c == '\n'));
    }
    [Fact]
    public void Add_BuildersOfOneAndManyChunks_ReadBackAsTheirText()
    {
        // A builder grown from a small capacity holds its text in several chunks; a reused one usually in one.
        var chunked = new System.Text.StringBuilder(4);
        for (int i = 0; i < 40; i++)
        {
            chunked.Append("MoveL ").Append(i).Append(';');
        }
        var single = new System.Text.StringBuilder(256).Append("movel(p[0.3, 0, 0.5, 0, 3.1416, 0], a=1, v=0.1)  # [Move to 300, 0, 500 mm]");
        var other = new System.Text.StringBuilder(2).Append("unicodé ").Append("✓ 日本 ").Append("🤖");
        int chunks = 0;
        foreach (ReadOnlyMemory<char> _ in chunked.GetChunks())
        {
            chunks++;
        }
        Assert.True(chunks > 1, "the test needs a builder of several chunks");
        var packed = new PackedLines();

        packed.Add(chunked);
        packed.Add(single);
        packed.Add(other);
        packed.Add(new System.Text.StringBuilder());

        Assert.Equal([chunked.ToString(), single.ToString(), "unicodé ✓ 日本 🤖", ""], packed);
        Assert.Equal(chunked.Length + single.Length + other.Length, packed.CharacterCount);
    }

    [Fact]
    public void Add_BuilderToEachSink_WritesTheSameLineAsItsString()
    {
        var text = new System.Text.StringBuilder(3).Append("  MoveL [[1,2,3]], v100, z5, tool0\\WObj:=WObj0;").Append("  ! [Move 1, 2, 3 mm]");
        var writer = new StringWriter();
        var list = new ListLineSink();
        using var memory = new MemorySpool();

        new WriterLineSink(writer, "\r\n").Add(text);
        list.Add(text);
        memory.Add(text);
        var moved = new ListLineSink();
        memory.MoveTo(moved);

        Assert.Equal(text + "\r\n", writer.ToString());
        Assert.Equal([text.ToString()], list.Lines);
        Assert.Equal([text.ToString()], moved.Lines);
    }

    [Fact]
    public void AppendAdopting_AfterLinesOfBothKinds_ReadsBackAllLinesAndTakesMoreAfter()
    {
        // Both sides span several blocks of ASCII and of other characters, so the block indices of the adopted lines move.
        List<string> first = SampleLines();
        first.Add("unicodé ✓ first");
        List<string> spooled = SampleLines().Select((l, i) => i % 50 == 0 ? "日本 " + l : l).ToList();
        var target = new PackedLines();
        var spool = new PackedLines();
        first.ForEach(l => target.Add(l));
        spooled.ForEach(l => spool.Add(l));

        target.AppendAdopting(spool);
        target.Add("after ASCII");
        target.Add("after ✓");

        List<string> expected = [.. first, .. spooled, "after ASCII", "after ✓"];
        Assert.Equal(expected, target);
        Assert.Equal(expected.Sum(l => (long)l.Length), target.CharacterCount);
        var copied = new char[target.CharacterCount + expected.Count];
        target.CopyTo(copied, "\n");
        Assert.Equal(string.Concat(expected.Select(l => l + "\n")), new string(copied));
    }

    [Fact]
    public void MemorySpool_MoveToListAfterHeader_KeepsHeaderThenSpooledLines()
    {
        var file = new ListLineSink();
        file.Add("MODULE Header");
        using var spool = new MemorySpool();
        spool.Add("  MoveL [[1,2,3]], v100, z5, tool0;");
        spool.Add("  ! ✓ not ASCII");

        spool.MoveTo(file);
        spool.Add("  ! the spool is empty again");
        var second = new ListLineSink();
        spool.MoveTo(second);
        file.Add("ENDMODULE");

        Assert.Equal(["MODULE Header", "  MoveL [[1,2,3]], v100, z5, tool0;", "  ! ✓ not ASCII", "ENDMODULE"], file.Lines);
        Assert.Equal(["  ! the spool is empty again"], second.Lines);
    }

    [Fact]
    public void Add_LinesOverSeveralChunksOfTheTable_EachIndexReadsItsLine()
    {
        // The table of lines is kept in chunks of 4,096 entries (the first one grows up to that): lines on both sides of each
        // boundary, read by index, in order and copied.
        var expected = Enumerable.Range(0, 4096 * 3 + 5).Select(i => i % 1000 == 7 ? "✓ " + i : "L" + i).ToList();
        var packed = new PackedLines();
        expected.ForEach(l => packed.Add(l));

        foreach (int i in (int[])[0, 15, 16, 2047, 2048, 4095, 4096, 4097, 8191, 8192, 12287, 12288, expected.Count - 1])
        {
            Assert.Equal(expected[i], packed[i]);
        }
        Assert.Equal(expected, packed);
        var copied = new char[packed.CharacterCount + expected.Count * 2];
        packed.CopyTo(copied, "\r\n");
        Assert.Equal(string.Concat(expected.Select(l => l + "\r\n")), new string(copied));
        Assert.Throws<ArgumentOutOfRangeException>(() => packed[expected.Count]);
        Assert.Throws<ArgumentOutOfRangeException>(() => packed[-1]);
    }

    [Fact]
    public void AppendAdopting_SeveralSpoolsWithLinesBetween_ReadsEveryLineInOrder()
    {
        // A file takes over several spools (one of them empty) with lines of its own before, between and after them: each
        // line keeps its place, by index, in order, copied and written.
        var target = new PackedLines();
        var expected = new List<string>();
        void Own(string line)
        {
            target.Add(line);
            expected.Add(line);
        }
        PackedLines Spool(int count, string prefix)
        {
            var spool = new PackedLines();
            for (int i = 0; i < count; i++)
            {
                string line = i % 333 == 1 ? prefix + " ✓ " + i : prefix + " " + i;
                spool.Add(line);
                expected.Add(line);
            }
            return spool;
        }

        Own("MODULE M");
        target.AppendAdopting(Spool(5000, "first"));
        Own("  ! between");
        target.AppendAdopting(Spool(0, "empty"));
        target.AppendAdopting(Spool(3, "second"));
        Own("ENDMODULE");

        Assert.Equal(expected.Count, target.Count);
        Assert.Equal(expected, target);
        Assert.Equal("  ! between", target[5001]);
        Assert.Equal("second 0", target[5002]);
        Assert.Equal("ENDMODULE", target[^1]);
        Assert.Equal(expected.Sum(l => (long)l.Length), target.CharacterCount);
        var writer = new StringWriter();
        target.WriteTo(writer, "\n");
        Assert.Equal(string.Concat(expected.Select(l => l + "\n")), writer.ToString());
    }

    /// <summary>Lines in three parts (an own part, an adopted spool of both kinds of lines, an own part again), over several table chunks.</summary>
    private static (PackedLines Packed, List<string> Lines) ThreeParts(int spooled, int lineLength)
    {
        var lines = new List<string>();
        var packed = new PackedLines();
        var spool = new PackedLines();
        void Add(PackedLines target, string line)
        {
            target.Add(line);
            lines.Add(line);
        }
        Add(packed, "MODULE M");
        Add(packed, "");
        for (int i = 0; i < spooled; i++)
        {
            Add(spool, i % 1001 == 7 ? "    ! é " + i : "    MoveL " + new string((char)('a' + i % 26), i % lineLength) + i.ToString(System.Globalization.CultureInfo.InvariantCulture));
        }
        packed.AppendAdopting(spool);
        Add(packed, "  ENDPROC");
        Add(packed, "ENDMODULE");
        return (packed, lines);
    }

    [Theory]
    [InlineData("\n")]
    [InlineData("\r\n")]
    public void CopyTo_LineRanges_EachRangeIsThoseLinesJoined(string newLine)
    {
        (PackedLines packed, List<string> lines) = ThreeParts(9000, 40);
        foreach ((int first, int end) in new[] { (0, 0), (0, 1), (1, 3), (2, 4098), (4000, 9004), (9001, 9004), (0, 9004), (4096, 8192) })
        {
            string expected = string.Concat(lines.Skip(first).Take(end - first).Select(l => l + newLine));
            var copied = new char[expected.Length];
            packed.CopyTo(copied, newLine, first, end);
            Assert.Equal(expected, new string(copied));
        }
    }

    [Fact]
    public void Middle_ThreePartsAndOnePart_IsTheFirstLineFromHalfTheText()
    {
        foreach ((PackedLines packed, List<string> lines) in new[] { ThreeParts(9000, 40), ThreeParts(1, 3) })
        {
            (int line, long start) = packed.Middle("\r\n");
            long total = lines.Sum(l => l.Length + 2L);
            long before = lines.Take(line).Sum(l => l.Length + 2L);
            Assert.Equal(before, start);
            Assert.True(before >= total / 2, $"line {line} starts at {before} of {total}");
            Assert.True(before - lines[line - 1].Length - 2 < total / 2, $"line {line - 1} already starts half-way");
        }
    }

    [Fact]
    public void ToText_LongEnoughForTwoThreads_IsTheLinesJoined()
    {
        // Over PackedLines.TwoThreadCharacters (4 Mi characters): copied in two halves at once, and the halves meet exactly.
        var robot = Robot.Create("Long", "ABB");
        robot.MoveTo(300, 0, 500);
        for (int i = 0; i < 40_000; i++)
        {
            robot.Move(i % 2 == 0 ? 1 : -1, 0.5, 0);
        }
        RobotProgramFile mod = robot.Compile().GetFile("mod")!;
        string text = mod.ToText("\r\n");

        Assert.True(text.Length >= PackedLines.TwoThreadCharacters, $"only {text.Length} characters");
        Assert.Equal(string.Concat(mod.Lines.Select(l => l + "\r\n")), text);
    }
}
