namespace Machina.Tests.Core;

/// <summary>Facade verbs against their instructions: a program issued with verbs and the same program given to Do agree.</summary>
public class RobotVerbTests
{
    private static void IssueEverything(Robot bot)
    {
        bot.Initialize();
        bot.Message("Start \"now\"");
        bot.Comment("first line\nsecond line");
        bot.SpeedTo(100);
        bot.Speed(-20);
        bot.AccelerationTo(500);
        bot.Acceleration(10);
        bot.PrecisionTo(2);
        bot.Precision(1);
        bot.MotionMode("Joint");
        bot.MotionMode(MotionType.Linear);
        bot.TransformTo(new Vector(100, 0, 200), Rotation.FlippedAroundY);
        bot.PushSettings();
        bot.Coordinates(ReferenceCS.Local);
        bot.Move(10, 0, 5);
        bot.Rotate(Vector.ZAxis, 45);
        bot.Transform(new Vector(1, 2, 3), Rotation.FromAxisAngle(Vector.XAxis, 10));
        bot.Transform(Rotation.FromAxisAngle(Vector.YAxis, -10), new Vector(3, 2, 1));
        bot.PopSettings();
        bot.MoveTo(150, 50, 250);
        bot.RotateTo(new Vector(-1, 0, 0), new Vector(0, 1, 0));
        bot.ArcMotion(10, 10, 0, 20, 0, 0);
        bot.ArcMotionTo(180, 60, 250, 190, 50, 250);
        bot.DefineTool("pen", 0, 50, 0, 0, 1, 0, -1, 0, 0, 0.5, 0, 25, 0);
        bot.AttachTool("pen");
        bot.Move(0, 0, -10);
        bot.DetachTool();
        bot.WriteDigital(2, true, true);
        bot.WriteDigital("DO_15", false);
        bot.WriteAnalog(0, 0.25);
        bot.WriteAnalog("AO_1", 3, true);
        bot.ExternalAxisTo(1, 100);
        bot.ExternalAxis(1, 5, ExternalAxesTarget.Cartesian);
        bot.ArmAngleTo(30);
        bot.ArmAngle(-5);
        bot.TemperatureTo(200, "Extruder");
        bot.Temperature(5, "bed", false);
        bot.ExtrusionRateTo(0.1);
        bot.ExtrusionRate(0.05);
        bot.Extrude();
        bot.Move(10, 0, 0);
        bot.Extrude(false);
        bot.CustomCode("! raw", true);
        bot.Wait(500);
        bot.AxesTo(0, 0, 0, 0, 90, 0);
        bot.Axes(10, 0, 0, 0, -10, 0);
        bot.Terminate();
    }

    [Fact]
    public void Do_InstructionsOfEveryVerb_RebuildTheSameProgramAndState()
    {
        var byVerbs = Robot.Create("Verbs", RobotType.ABB);
        IssueEverything(byVerbs);
        string text = string.Join("\n", byVerbs.GetProgramActions().Select(a => a.ToInstruction()));

        var byText = Robot.Create("Text", RobotType.ABB);
        byText.Do(text);

        Assert.Equal(byVerbs.GetProgramActions(), byText.GetProgramActions());
        RobotState a = byVerbs.GetCurrentState(), b = byText.GetCurrentState();
        Assert.Equal(a.Axes, b.Axes);
        Assert.Equal(a.Settings, b.Settings);
        Assert.Equal(a.ExternalAxesCartesian, b.ExternalAxesCartesian);
        Assert.Equal(a.ExternalAxesJoints, b.ExternalAxesJoints);
        Assert.Equal(a.ArmAngle, b.ArmAngle);
        Assert.Equal(a.DigitalOutputs, b.DigitalOutputs);
        Assert.Equal(a.AnalogOutputs, b.AnalogOutputs);
        Assert.Equal((a.ExtruderTemperature, a.BedTemperature), (b.ExtruderTemperature, b.BedTemperature));
        Assert.Equal(a.ExtrudedLength, b.ExtrudedLength, 9);
        Assert.Equal(a.DefinedTools["pen"], b.DefinedTools["pen"]);
        Assert.Equal(47, byText.GetProgramActions().Count);
        Assert.Equal(new Joints(10, 0, 0, 0, 80, 0), b.Axes);
        Assert.Equal(new ExternalAxes(105), b.ExternalAxesCartesian);
        Assert.Equal(new ExternalAxes(100), b.ExternalAxesJoints);
        Assert.Equal(0.15 * 10, b.ExtrudedLength, 12);
    }

    [Fact]
    public void Issue_Null_ThrowsArgumentNull()
    {
        var ex = Assert.Throws<ArgumentNullException>(() => Robot.Create("Bot", RobotType.ABB).Issue(null!));

        Assert.Equal("action", ex.ParamName);
    }

    [Fact]
    public void Do_Null_ThrowsArgumentNull()
    {
        Assert.Throws<ArgumentNullException>(() => Robot.Create("Bot", RobotType.ABB).Do(null!));
    }

#pragma warning disable CS0618 // the obsolete Attach/Detach pair is kept for old scripts
    [Fact]
    public void Attach_Obsolete_DefinesAndAttachesInTwoActions()
    {
        var bot = PoseAt(100, 0, 200);
        Tool tool = Tool.Create("pen", new Vector(0, 0, 100), Rotation.Identity);

        Assert.True(bot.Attach(tool));
        Assert.Equal(new Point(100, 0, 100), bot.GetCurrentPosition());
        Assert.True(bot.Detach());

        Assert.Equal<RobotAction>([new ActionDefineTool(tool), new ActionAttachTool("pen"), new ActionDetachTool()], bot.GetProgramActions().Skip(1));
        Assert.Equal(new Point(100, 0, 200), bot.GetCurrentPosition());
    }
#pragma warning restore CS0618

    private static Robot PoseAt(double x, double y, double z)
    {
        var bot = Robot.Create("Bot", RobotType.ABB);
        bot.MoveTo(x, y, z);
        return bot;
    }
}
