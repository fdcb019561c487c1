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

/// <summary>A multi-statement Do is one unit even when other threads issue at the same time.</summary>
public class DoConcurrencyTests
{
    [Fact]
    public void DoFromTwoThreads_KeepsEachTextsStatementsTogether()
    {
        const int rounds = 3000;
        var bot = Robot.Create("Bot", RobotType.ABB);
        using var start = new Barrier(2);
        Thread[] threads = [.. new[] { "Wait(1); Wait(2); Wait(3);", "Wait(7); Wait(8); Wait(9);" }.Select(text => new Thread(() =>
        {
            start.SignalAndWait();
            for (int i = 0; i < rounds; i++)
            {
                bot.Do(text);
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

        long[] waits = [.. bot.GetProgramActions().Cast<ActionWait>().Select(w => w.Millis)];
        Assert.Equal(6 * rounds, waits.Length);
        int broken = Enumerable.Range(0, 2 * rounds).Count(k => waits[3 * k + 1] != waits[3 * k] + 1 || waits[3 * k + 2] != waits[3 * k] + 2);
        Assert.Equal(0, broken);
    }

    [Fact]
    public void DoWhoseLaterStatementBecomesImpossible_IsRefusedWholeEvenUnderContention()
    {
        // Two threads each pop twice from a stack that only holds enough for some of them: every Do is all or nothing.
        var bot = Robot.Create("Bot", RobotType.ABB);
        for (int i = 0; i < 1000; i++)
        {
            bot.PushSettings();
        }
        int issued = 0;
        using var start = new Barrier(2);
        Thread[] threads = [.. Enumerable.Range(0, 2).Select(_ => new Thread(() =>
        {
            start.SignalAndWait();
            for (int i = 0; i < 400; i++)
            {
                try
                {
                    bot.Do("PopSettings(); PopSettings();");
                    Interlocked.Increment(ref issued);
                }
                catch (ActionRefusedException)
                {
                }
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

        Assert.Equal(1000 + 2 * issued, bot.GetProgramActions().Count);
        Assert.Equal(1000 - 2 * issued, bot.GetCurrentState().SettingsDepth);
    }

    [Fact]
    public void DoWithSeveralStatements_RaisesOneEventPerStatementWithItsOwnSnapshot()
    {
        var bot = Robot.Create("Bot", RobotType.ABB);
        var events = new List<ActionIssuedArgs>();
        bot.ActionIssued += (_, e) => events.Add(e);

        bot.Do("MoveTo(1, 2, 3); Move(10, 0, 0); SpeedTo(50);");

        Assert.Equal([1, 2, 3], events.Select(e => e.LastAction.Id));
        Assert.Equal([new Vector(1, 2, 3), new Vector(11, 2, 3), new Vector(11, 2, 3)], events.Select(e => e.State.Position!.Value));
        Assert.Equal([20.0, 20.0, 50.0], events.Select(e => e.State.Speed));
        Assert.Same(bot.GetProgramActions()[1], events[1].LastAction);
    }
}
