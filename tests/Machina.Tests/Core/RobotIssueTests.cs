using Machina.Tests.Support;
using System.Globalization;

namespace Machina.Tests.Core;

/// <summary>Issuing: ids, refusals that change nothing, Do atomicity, the ActionIssued payload and culture independence.</summary>
public class RobotIssueTests
{
    [Fact]
    public void Issue_Refusals_LeaveStateAndIdCounterUnchanged()
    {
        var bot = Robot.Create("Bot", RobotType.ABB);
        bot.MoveTo(10, 20, 30);
        bot.SpeedTo(50);
        RobotState before = bot.GetCurrentState();

        Assert.Throws<ActionRefusedException>(() => bot.PopSettings());
        Assert.Throws<ActionRefusedException>(() => bot.AttachTool("none"));
        Assert.Throws<ActionRefusedException>(() => bot.Axes(1, 1, 1, 1, 1, 1));
        Assert.Throws<ActionRefusedException>(() => bot.Speed(-60));
        Assert.Throws<ActionRefusedException>(() => bot.ExternalAxis(3, 1));
        Assert.Throws<ArgumentException>(() => bot.MoveTo(double.NaN, 0, 0));
        Assert.Throws<ArgumentException>(() => bot.Rotate(0, 0, 0, 10));

        StateAssert.Same(before, bot.GetCurrentState());
        bot.Wait(1);
        Assert.Equal([1, 2, 3], bot.GetProgramActions().Select(a => a.Id));
    }

    [Fact]
    public void Do_OneStatement_IssuesIt()
    {
        var bot = Robot.Create("Bot", RobotType.ABB);

        Assert.True(bot.Do("MoveTo(400,300,500);"));

        Assert.Equal(new Point(400, 300, 500), bot.GetCurrentPosition());
        Assert.Equal(1, bot.GetProgramActions()[0].Id);
    }

    [Fact]
    public void Do_SeveralStatements_IssuesAllInOrder()
    {
        var bot = Robot.Create("Bot", RobotType.ABB);

        bot.Do("SpeedTo(100); MoveTo(400, 300, 500); // start\nRotate(0, 1, 0, -90); Move(0, 0, 250);");

        Assert.Equal(new Point(400, 300, 750), bot.GetCurrentPosition());
        Assert.Equal([1, 2, 3, 4], bot.GetProgramActions().Select(a => a.Id));
    }

    [Fact]
    public void Do_ThirdStatementRefused_IssuesNothing()
    {
        var bot = Robot.Create("Bot", RobotType.ABB);
        bot.MoveTo(1, 2, 3);
        var issued = new List<ActionIssuedArgs>();
        bot.ActionIssued += (_, e) => issued.Add(e);
        RobotState before = bot.GetCurrentState();

        var ex = Assert.Throws<ActionRefusedException>(() => bot.Do("Move(1, 0, 0); SpeedTo(5); AttachTool(\"nope\");"));

        Assert.Equal(new ActionAttachTool("nope"), ex.Action);
        StateAssert.Same(before, bot.GetCurrentState());
        Assert.Empty(issued);
        Assert.Single(bot.GetProgramActions());
        bot.Wait(1);
        Assert.Equal(2, bot.GetProgramActions()[1].Id);
    }

    [Fact]
    public void Do_ParseErrorInSecondLine_IssuesNothing()
    {
        var bot = Robot.Create("Bot", RobotType.ABB);

        var ex = Assert.Throws<InstructionParseException>(() => bot.Do("MoveTo(1,2,3);\nWait(1.5);"));

        Assert.Equal((2, 6), (ex.Line, ex.Column));
        Assert.Empty(bot.GetProgramActions());
        Assert.Null(bot.GetCurrentPosition());
    }

    [Fact]
    public void Do_RelativeAfterDefineAndAttachInSameText_IsCheckedInSequence()
    {
        var bot = Robot.Create("Bot", RobotType.ABB);

        bot.Do("MoveTo(100,0,200); DefineTool(\"t\",0,50,0,0,1,0,-1,0,0,1,0,0,0); AttachTool(\"t\"); DetachTool();");

        Assert.Equal(4, bot.GetProgramActions().Count);
        Assert.Equal(100, bot.GetCurrentPosition()!.Value.X, 9);
        Assert.Equal(0, bot.GetCurrentPosition()!.Value.Y, 9);
    }

    [Fact]
    public void ActionIssued_Payload_IsASnapshotThatLaterActionsDoNotChange()
    {
        var bot = Robot.Create("Bot", RobotType.ABB);
        var events = new List<ActionIssuedArgs>();
        bot.ActionIssued += (_, e) => events.Add(e);

        bot.MoveTo(1, 2, 3);
        bot.WriteDigital(1, true);
        bot.ExternalAxisTo(1, 5);
        bot.Move(10, 0, 0);
        bot.WriteDigital(1, false);
        bot.ExternalAxis(1, 5);
        bot.SpeedTo(80);

        Assert.Equal(new Vector(1, 2, 3), events[0].Position);
        Assert.Equal(20, events[0].State.Speed);
        Assert.True(events[1].State.DigitalOutputs["1"]);
        Assert.Equal(new ExternalAxes(5), events[2].ExternalAxes);
        Assert.Equal(new Vector(11, 2, 3), events[3].Position);
        Assert.Equal(new ExternalAxes(10), events[5].ExternalAxes);
        Assert.Same(events[6].LastAction, bot.GetProgramActions()[6]);
        Assert.Equal(7, events[6].LastAction.Id);
        Assert.Equal(80, events[6].State.Speed);
        Assert.Equal(
            "{\"event\":\"action-issued\",\"last\":\"ExternalAxisTo(1,5);\",\"id\":3,\"pos\":[1,2,3],\"ori\":[-1,0,0,0,1,0],\"quat\":[0,0,1,0],\"axes\":null,\"extax\":[5,null,null,null,null,null],\"conf\":null}",
            events[2].ToJsonString());
    }

    [Fact]
    public void ActionIssued_ThrowingHandler_DoesNotStopIssuingOrOtherHandlers()
    {
        var bot = Robot.Create("Bot", RobotType.ABB);
        var log = new List<LogEntry>();
        bot.Logger.Logged += (_, e) => log.Add(e);
        int secondHandlerCalls = 0;
        bot.ActionIssued += (_, _) => throw new InvalidOperationException("boom");
        bot.ActionIssued += (_, _) => secondHandlerCalls++;

        Assert.True(bot.MoveTo(1, 2, 3));
        Assert.True(bot.Move(1, 0, 0));

        Assert.Equal(2, secondHandlerCalls);
        Assert.Equal(new Point(2, 2, 3), bot.GetCurrentPosition());
        Assert.Equal(2, log.Count(e => e.Level == LogLevel.ERROR && e.Message == "An event handler threw InvalidOperationException: boom"));
    }

    [Fact]
    public void ActionIssued_SenderIsTheRobot()
    {
        var bot = Robot.Create("Bot", RobotType.ABB);
        object? sender = null;
        bot.ActionIssued += (s, _) => sender = s;

        bot.Wait(1);

        Assert.Same(bot, sender);
    }

    [Fact]
    public void Issue_UnderGermanCulture_TextsAreInvariant()
    {
        static (string[] Instructions, string[] Descriptions) HelloRobotTexts()
        {
            var bot = Robot.Create("HelloRobot", "ABB");
            bot.Message("Hello Robot!");
            bot.SpeedTo(100.5);
            bot.MoveTo(400.25, 300, 500);
            bot.Rotate(0, 1, 0, -90.5);
            bot.Move(0, 0, 250.75);
            bot.WriteAnalog(1, 0.25);
            bot.TemperatureTo(205.5, "extruder");
            bot.Wait(2000);
            bot.AxesTo(0, 0, 0, 0, 90.5, 0);
            var actions = bot.GetProgramActions();
            return ([.. actions.Select(a => a.ToInstruction())], [.. actions.Select(a => a.Describe())]);
        }

        CultureInfo original = CultureInfo.CurrentCulture;
        (string[] Instructions, string[] Descriptions) german;
        try
        {
            CultureInfo.CurrentCulture = CultureInfo.GetCultureInfo("de-DE");
            german = HelloRobotTexts();
        }
        finally
        {
            CultureInfo.CurrentCulture = original;
        }
        CultureInfo.CurrentCulture = CultureInfo.InvariantCulture;
        try
        {
            var invariant = HelloRobotTexts();
            Assert.Equal(invariant.Instructions, german.Instructions);
            Assert.Equal(invariant.Descriptions, german.Descriptions);
        }
        finally
        {
            CultureInfo.CurrentCulture = original;
        }
        Assert.Equal("MoveTo(400.25,300,500);", german.Instructions[2]);
        Assert.Equal("Move to [400.25, 300, 500] mm", german.Descriptions[2]);
        Assert.Equal("Set motion speed to 100.5 mm/s or deg/s", german.Descriptions[1]);
    }

    [Fact]
    public void Getters_AfterHelloRobot_MatchThePaper()
    {
        var bot = Robot.Create("HelloRobot", "ABB");
        bot.Do("Message(\"Hello Robot!\"); SpeedTo(100); MoveTo(400,300,500); Rotate(0,1,0,-90); Move(0,0,250); Wait(2000);");

        Assert.Equal(new Point(400, 300, 750), bot.GetCurrentPosition());
        PoseAssertCore.Axes(new Vector(0, 0, -1), new Vector(1, 0, 0), bot.GetCurrentRotation()); // Ry(-90)·Ry(180) = Ry(90)
        Assert.Equal(100, bot.GetCurrentSpeed());
        Assert.Equal(30, bot.GetCurrentAcceleration());
        Assert.Equal(5, bot.GetCurrentPrecision());
        Assert.Null(bot.GetCurrentAxes());

        bot.AxesTo(0, 0, 0, 0, 90, 0);
        Assert.Equal(new Joints(0, 0, 0, 0, 90, 0), bot.GetCurrentAxes());
        Assert.Null(bot.GetCurrentPosition());
    }
}

internal static class PoseAssertCore
{
    internal static void Axes(Vector xAxis, Vector zAxis, Rotation? actual)
    {
        Assert.NotNull(actual);
        Assert.True((actual.Value.XAxis - xAxis).Length < 1e-9, $"X axis was {actual.Value.XAxis}");
        Assert.True((actual.Value.ZAxis - zAxis).Length < 1e-9, $"Z axis was {actual.Value.ZAxis}");
    }
}

public class RobotConcurrencyTests
{
    [Fact]
    public void ActionIssued_TwoThreadsIssuing_EachPayloadShowsItsOwnAction()
    {
        var bot = Robot.Create("Busy", RobotType.ABB);
        bot.MoveTo(0, 0, 0);
        var mismatches = 0;
        bot.ActionIssued += (_, e) =>
        {
            if (e.State.LastAction is not { } last || last.Id != e.LastAction.Id)
            {
                Interlocked.Increment(ref mismatches);
            }
        };

        Parallel.For(0, 2, _ =>
        {
            for (int i = 0; i < 2000; i++)
            {
                bot.Move(1, 0, 0);
            }
        });

        Assert.Equal(0, mismatches);
        Assert.Equal(new Point(4000, 0, 0), bot.GetCurrentPosition());
        Assert.Equal(Enumerable.Range(1, 4001), bot.GetProgramActions().Select(a => a.Id));
    }

    [Fact]
    public void Temperature_TypedPartOverload_IsRelative()
    {
        var bot = Robot.Create("Printer", RobotType.MARLIN);
        bot.TemperatureTo(50, RobotPartType.Chamber);
        bot.Temperature(5, RobotPartType.Chamber, false);

        Assert.Equal(55, bot.GetCurrentState().ChamberTemperature);
        Assert.Equal(new ActionTemperature(5, RobotPartType.Chamber, false, true), bot.GetProgramActions()[1]);
    }
}
