using System.Text;

namespace Machina.Tests.Programs;

/// <summary>The piecewise reader gives the same actions, positions and errors as parsing the whole text at once.</summary>
public class InstructionReaderTests
{
    /// <summary>Far more text than one piece, with statements over several lines, several statements per line, comments and CRLF.</summary>
    private static string LongText(int statements, string newLine)
    {
        var text = new StringBuilder("\uFEFFMoveTo(300, 0, 500);" + newLine);
        for (int i = 0; i < statements; i++)
        {
            text.Append((i % 7) switch
            {
                0 => $"Move(1.5,{newLine}   -2, // a comment inside{newLine}   0.25);{newLine}",
                1 => $"Wait({i}); Message(\"line {i}; with \\\"quotes\\\"\");{newLine}",
                2 => $"// just a comment {i}{newLine}{newLine}",
                3 => $"TransformTo({newLine}{newLine}{newLine}  300, {i % 100}, 500,{newLine} 1, 0, 0,{newLine} 0, 1, 0{newLine}){newLine};{newLine}",
                _ => $"  Move({i % 13}, 0, 1);{newLine}",
            });
        }
        return text.ToString();
    }

    private static List<(RobotAction Action, int Line, int Column)> ReadAll(string text, int readSize)
    {
        var reader = new InstructionReader(new ChunkedReader(text, readSize));
        var all = new List<(RobotAction, int, int)>();
        while (reader.Next() is RobotAction action)
        {
            all.Add((action, reader.Line, reader.Column));
        }
        return all;
    }

    [Theory]
    [InlineData("\n", 4096)]
    [InlineData("\r\n", 1000)]
    [InlineData("\n", 7)]
    public void Next_TextOfManyPieces_SameActionsAsParse(string newLine, int readSize)
    {
        string text = LongText(20_000, newLine);
        Assert.True(text.Length > 20 * InstructionReader.PieceSize);

        List<(RobotAction Action, int Line, int Column)> read = ReadAll(text, readSize);

        Assert.Equal(Instructions.Parse(text), read.Select(r => r.Action));
        // The last TransformTo starts on the line after its predecessor; check positions against a count of the text.
        int index = text.LastIndexOf("TransformTo(", StringComparison.Ordinal);
        int line = text[..index].Count(c => c == '\n') + 1;
        int column = index - text.LastIndexOf('\n', index);
        Assert.Contains(read, r => r.Line == line && r.Column == column && r.Action is ActionTransformation);
    }

    [Fact]
    public void Next_OneLineLongerThanAPiece_IsRead()
    {
        string line = string.Concat(Enumerable.Repeat("Move(1, 0, 0); ", 3 * InstructionReader.PieceSize / 15));
        string text = "MoveTo(0, 0, 0);\n" + line + "\nWait(5);";

        List<(RobotAction Action, int Line, int Column)> read = ReadAll(text, 1 << 12);

        Assert.Equal(Instructions.Parse(text), read.Select(r => r.Action));
        Assert.Equal((3, 1), (read[^1].Line, read[^1].Column));
    }

    [Fact]
    public void Next_EndlessLine_RefusedWithItsLine_MemoryBounded()
    {
        // 2^30 characters on one line used to end the process; the text is made as it is read, never held whole here.
        var reader = new InstructionReader(new EndlessReader("MoveTo(0, 0, 0);\nWait(1);\n", "Move(1, 0, 0); "));
        Assert.IsType<ActionTranslation>(reader.Next());
        var e = Assert.Throws<InstructionParseException>(() => { while (reader.Next() is not null) { } });
        Assert.Equal($"Line 3, column 1: this line is longer than {InstructionReader.MaxLineChars} characters, the most Machina reads as one line; is the file a program?", e.Message);
    }

    [Fact]
    public void Next_EndlessStatementOverManyLines_RefusedWithWhereItStarts()
    {
        var reader = new InstructionReader(new EndlessReader("Wait(1);\n  Move(1,\n", "  // a comment, and the parenthesis never closed\n"));
        Assert.NotNull(reader.Next());
        var e = Assert.Throws<InstructionParseException>(() => { while (reader.Next() is not null) { } });
        Assert.Equal($"Line 2, column 3: this statement is longer than {InstructionReader.MaxLineChars} characters, the most Machina reads as one statement (is a quote or a parenthesis left open?)", e.Message);
    }

    /// <summary>A start, then one text repeated forever, made as it is read.</summary>
    private sealed class EndlessReader(string start, string repeated) : TextReader
    {
        private long _at;

        public override int Read(char[] buffer, int index, int count)
        {
            for (int i = 0; i < count; i++, _at++)
            {
                buffer[index + i] = _at < start.Length ? start[(int)_at] : repeated[(int)((_at - start.Length) % repeated.Length)];
            }
            return count;
        }
    }

    [Fact]
    public void Next_UnclosedStatementAtTheEnd_SameErrorAsParse()
    {
        string text = LongText(5000, "\n") + "Move(1,\n 2,\n";

        var error = Assert.Throws<InstructionParseException>(() => ReadAll(text, 4096));

        var expected = Assert.Throws<InstructionParseException>(() => Instructions.Parse(text));
        Assert.Equal((expected.Line, expected.Column, expected.Message), (error.Line, error.Column, error.Message));
    }

    [Fact]
    public void Next_EmptyText_NoAction()
    {
        Assert.Empty(ReadAll("", 10));
        Assert.Empty(ReadAll("\n// nothing\n", 10));
    }

    /// <summary>A reader that returns at most <c>size</c> characters per call, as a slow stream would.</summary>
    private sealed class ChunkedReader(string text, int size) : TextReader
    {
        private int _pos;

        public override int Read(char[] buffer, int index, int count)
        {
            int n = Math.Min(Math.Min(count, size), text.Length - _pos);
            text.CopyTo(_pos, buffer, index, n);
            _pos += n;
            return n;
        }
    }
}
