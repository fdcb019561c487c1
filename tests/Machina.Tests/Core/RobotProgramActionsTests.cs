namespace Machina.Tests.Core;

/// <summary>The robot's program list keeps its actions in chunks: order, count and clearing across the chunks' edges.</summary>
public class RobotProgramActionsTests
{
    [Theory]
    [InlineData(0)]
    [InlineData(1)]
    [InlineData(5)]
    [InlineData(RobotProgramActions.ChunkSize)]
    [InlineData(RobotProgramActions.ChunkSize + 1)]
    [InlineData(3 * RobotProgramActions.ChunkSize + 7)]
    public void Add_ManyActions_ToArrayKeepsEveryOneInOrder(int count)
    {
        var list = new RobotProgramActions();
        var added = new RobotAction[count];
        for (int i = 0; i < count; i++)
        {
            added[i] = new ActionWait(i);
            list.Add(added[i]);
        }

        RobotAction[] all = list.ToArray();

        Assert.Equal(count, list.Count);
        Assert.Equal(count, all.Length);
        for (int i = 0; i < count; i++)
        {
            Assert.Same(added[i], all[i]);
        }
    }

    [Theory]
    [InlineData(0)]
    [InlineData(3)]
    [InlineData(RobotProgramActions.ChunkSize)]
    [InlineData(2 * RobotProgramActions.ChunkSize + 5)]
    public void Snapshot_ActionsAddedOrClearedAfterIt_KeepsExactlyTheActionsOfItsMoment(int count)
    {
        var list = new RobotProgramActions();
        var added = new RobotAction[count];
        for (int i = 0; i < count; i++)
        {
            added[i] = new ActionWait(i);
            list.Add(added[i]);
        }

        RobotProgramSnapshot snapshot = list.Snapshot();
        for (int i = 0; i < RobotProgramActions.ChunkSize + 3; i++)
        {
            list.Add(new ActionWait(100_000 + i)); // grows the first chunk, fills the last one, starts new ones
        }
        list.Clear();
        list.Add(new ActionWait(7));

        Assert.Equal(count, snapshot.Count);
        Assert.Equal(added, snapshot.ToArray());
        var byChunk = new List<RobotAction>();
        for (int c = 0; c < snapshot.ChunkCount; c++)
        {
            byChunk.AddRange(snapshot.Chunk(c).ToArray());
        }
        Assert.Equal(added, byChunk);
    }

    [Fact]
    public void Clear_AfterSeveralChunks_StartsEmptyAndKeepsNewActionsOnly()
    {
        var list = new RobotProgramActions();
        for (int i = 0; i < 2 * RobotProgramActions.ChunkSize + 3; i++)
        {
            list.Add(new ActionWait(i));
        }
        list.Clear();
        var after = new ActionWait(99);
        list.Add(after);

        Assert.Equal(1, list.Count);
        Assert.Same(after, Assert.Single(list.ToArray()));
    }

    [Fact]
    public void Robot_IssuesMoreThanAChunk_CompilesAndListsThemAllInOrder()
    {
        var bot = Robot.Create("Chunks", RobotType.MACHINA);
        bot.MoveTo(300, 0, 500);
        int moves = RobotProgramActions.ChunkSize + 10;
        for (int i = 0; i < moves; i++)
        {
            bot.Move(1, 0, 0);
        }

        IReadOnlyList<RobotAction> actions = bot.GetProgramActions();

        Assert.Equal(moves + 1, actions.Count);
        Assert.Equal(Enumerable.Range(1, moves + 1), actions.Select(a => a.Id));
        Assert.Equal(moves + 1, Instructions.Parse(bot.Compile().Files[0].ToText()).Count);
    }
}
