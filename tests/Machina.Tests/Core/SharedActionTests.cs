namespace Machina.Tests.Core;

/// <summary>One action object issued to several robots at the same time: each robot keeps its own copy with its own id.</summary>
public class SharedActionTests
{
    [Fact]
    public void SameActionsIssuedByTwoRobotsInParallel_EachRobotNumbersItsOwnCopies()
    {
        const int count = 20000;
        RobotAction[] shared = [.. Enumerable.Range(0, count).Select(i => (RobotAction)new ActionTranslation(new Vector(i, 0, 0), false))];
        Robot[] bots = [Robot.Create("A", RobotType.ABB), Robot.Create("B", RobotType.ABB)];
        using var start = new Barrier(bots.Length);

        Thread[] threads = [.. bots.Select(bot => new Thread(() =>
        {
            start.SignalAndWait();
            foreach (RobotAction action in shared)
            {
                bot.Issue(action);
            }
        }))];
        foreach (Thread t in threads)
        {
            t.Start();
        }
        foreach (Thread t in threads)
        {
            t.Join();
        }

        IReadOnlyList<RobotAction> a = bots[0].GetProgramActions(), b = bots[1].GetProgramActions();
        Assert.Equal(Enumerable.Range(1, count), a.Select(x => x.Id));
        Assert.Equal(Enumerable.Range(1, count), b.Select(x => x.Id));
        Assert.Equal(0, Enumerable.Range(0, count).Count(i => ReferenceEquals(a[i], b[i])));
        Assert.Equal(new Point(count - 1, 0, 0), bots[0].GetCurrentPosition());
    }

    [Fact]
    public void RefusedActionObject_StaysUnissuedAndCanBeIssuedLater()
    {
        var bot = Robot.Create("Bot", RobotType.ABB);
        var move = new ActionTranslation(new Vector(1, 0, 0), true);

        var ex = Assert.Throws<ActionRefusedException>(() => bot.Issue(move));

        Assert.Equal(-1, move.Id);
        Assert.Equal(-1, ex.Action.Id);
        bot.MoveTo(0, 0, 0);
        bot.Issue(move);
        Assert.Equal(2, move.Id);
        Assert.Same(move, bot.GetProgramActions()[1]);
    }
}
