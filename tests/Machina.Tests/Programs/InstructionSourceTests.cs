namespace Machina.Tests.Programs;

/// <summary>The source that re-reads instruction text for each compiler pass, on a reading thread of its own.</summary>
public class InstructionSourceTests
{
    private static string Moves(int count) => "MoveTo(0, 0, 0);\n" + string.Concat(Enumerable.Range(1, count).Select(i => $"Move({i % 5}, 0, 0);\n"));

    [Fact]
    public void Enumerate_TwoPasses_SameActionsWithIdsFromOne()
    {
        string text = Moves(3000);
        var source = new InstructionSource(() => new StringReader(text), CancellationToken.None);

        List<RobotAction> first = [.. source];
        List<RobotAction> second = [.. source];

        Assert.Equal(Instructions.Parse(text), first);
        Assert.Equal(first, second);
        Assert.Equal(Enumerable.Range(1, 3001), second.Select(a => a.Id));
        Assert.Equal(3001, source.Count);
        Assert.False(ReferenceEquals(first[5], second[5]));
    }

    [Fact]
    public void Enumerate_ManyBatches_EveryActionInOrderAtItsLine()
    {
        // Five full batches and a part of one: the batches the compiler is done with are filled again by the reading thread.
        int count = 5 * InstructionSource.BatchSize + 7;
        string text = string.Concat(Enumerable.Range(0, count).Select(i => $"MoveTo({i}, {i % 7}, 0);\n"));
        var source = new InstructionSource(() => new StringReader(text), CancellationToken.None);

        for (int pass = 0; pass < 2; pass++)
        {
            int id = 0;
            foreach (RobotAction action in source)
            {
                Assert.Equal(++id, action.Id);
                var move = Assert.IsType<ActionTranslation>(action);
                Assert.Equal(new Vector(id - 1, (id - 1) % 7, 0), move.Translation);
                Assert.Equal((id, 1), source.PositionOf(id));
            }
            Assert.Equal(count, id);
        }
        Assert.Equal(count, source.Count);
    }

    [Theory]
    [InlineData(0, true)]
    [InlineData(65_530, true)]      // "CustomCode" cut by the end of the first 64 K block
    [InlineData(65_536, true)]
    [InlineData(200_000, true)]
    [InlineData(-1, false)]
    public void MayContain_WordAnywhere_FoundEvenAcrossBlocks(int at, bool expected)
    {
        string filler = new('x', 300_000);
        string text = at < 0 ? filler : filler[..at] + "CustomCode" + filler[at..];
        var source = new InstructionSource(() => new StringReader(text), CancellationToken.None);

        Assert.Equal(expected, source.MayContain(["Acceleration", "CustomCode"]));
    }

    [Theory]
    [InlineData("Tool", 65_530)]     // found by its "l": the word starts in one block and ends in the next
    [InlineData("Tool", 65_533)]
    [InlineData("Read", 65_532)]
    [InlineData("Analog", 65_531)]
    [InlineData("Acceleration", 65_535)]
    [InlineData("Speed", 0)]
    [InlineData("Read", 299_990)]
    public void MayContain_WordFoundByALaterLetter_FoundInAToolpathEvenAcrossBlocks(string word, int at)
    {
        // Text made of the motion instructions' letters (MoveTo, Rotate), which hold the first letters of Tool and Read.
        string filler = string.Concat(Enumerable.Repeat("MoveTo(1,2,3);Rotate(0,0,1,5);\n", 10_000))[..300_000];
        string[] words = ["Speed", "Precision", "Settings", "Tool", "CustomCode", "Digital", "Analog", "Acceleration", "Read"];
        var without = new InstructionSource(() => new StringReader(filler), CancellationToken.None);
        string text = filler[..at] + word + filler[at..];
        var with = new InstructionSource(() => new StringReader(text), CancellationToken.None);
        string almost = filler[..at] + word[..^1] + "_" + filler[at..];
        var cut = new InstructionSource(() => new StringReader(almost), CancellationToken.None);

        Assert.False(without.MayContain(words));
        Assert.True(with.MayContain(words));
        Assert.True(with.MayContain([word]));
        Assert.False(cut.MayContain([word]));
    }

    [Fact]
    public void CompileToFolder_DeclarationsOnlyInLaterText_StillDeclared()
    {
        // The survey pass is skipped only when the text cannot hold what it looks for; here it must run and find both.
        string folder = Path.Combine(Path.GetTempPath(), "machina-survey-" + Guid.NewGuid().ToString("N"));
        try
        {
            string text = Moves(50_000) + "CustomCode(\"DECL INT counter\", true);\nAccelerationTo(500);\nMove(1, 0, 0);\n";
            Instructions.CompileToFolder(new StringReader(text), RobotType.KUKA, folder, programName: "Survey");

            string src = File.ReadAllText(Path.Combine(folder, "Survey.src"));
            var robot = Robot.Create("Survey", RobotType.KUKA);
            robot.Do(text);
            Assert.Contains("DECL INT counter", src);
            Assert.Equal(robot.Compile().Files.Single(f => f.FileName == "Survey.src").ToText(), src);
        }
        finally
        {
            if (Directory.Exists(folder))
            {
                Directory.Delete(folder, recursive: true);
            }
        }
    }

    [Fact]
    public void Enumerate_ReaderFailsHalfWay_StatementsBeforeThenTheError()
    {
        string text = Moves(20_000);
        var source = new InstructionSource(() => new FailingReader(text, failAt: text.Length / 2), CancellationToken.None);
        int seen = 0;

        var error = Assert.Throws<IOException>(() =>
        {
            foreach (RobotAction action in source)
            {
                Assert.Equal(++seen, action.Id);
            }
        });

        Assert.Equal("disk gone", error.Message);
        Assert.InRange(seen, 1000, 10_000);
    }

    [Fact]
    public void Enumerate_StoppedEarly_ReadingThreadEnds()
    {
        var source = new InstructionSource(() => new StringReader(Moves(200_000)), CancellationToken.None);

        List<RobotAction> firstTen = [.. source.Take(10)];

        Assert.Equal(Enumerable.Range(1, 10), firstTen.Select(a => a.Id));
        Assert.Equal(0, source.Count);
        Assert.Equal((10, 1), source.PositionOf(10));
    }

    [Fact]
    public void PositionOf_CurrentAction_ItsLineAndColumn()
    {
        var source = new InstructionSource(() => new StringReader("MoveTo(0, 0, 0);\n\n  Wait(5); Move(1, 0, 0);\n"), CancellationToken.None);
        var positions = new List<(int, int)?>();
        foreach (RobotAction action in source)
        {
            positions.Add(source.PositionOf(action.Id));
            Assert.Null(source.PositionOf(action.Id + 1));
        }
        Assert.Equal([(1, 1), (3, 3), (3, 12)], positions);
    }

    /// <summary>Gives the text in small reads, then throws an IOException at <c>failAt</c>.</summary>
    private sealed class FailingReader(string text, int failAt) : TextReader
    {
        private int _pos;

        public override int Read(char[] buffer, int index, int count)
        {
            if (_pos >= failAt)
            {
                throw new IOException("disk gone");
            }
            int n = Math.Min(Math.Min(count, 1000), failAt - _pos);
            text.CopyTo(_pos, buffer, index, n);
            _pos += n;
            return n;
        }
    }
}
