namespace Machina.Tests.Support;

/// <summary>The whole programs every compiler is checked against (golden files in Golden/&lt;BRAND&gt;/&lt;Name&gt;.&lt;ext&gt;).</summary>
public static class ReferencePrograms
{
    /// <summary>Program name → the actions it issues.</summary>
    public static IReadOnlyDictionary<string, Action<Robot>> All { get; } = new Dictionary<string, Action<Robot>>
    {
        ["HelloRobot"] = HelloRobot,
        ["SquarePushPop"] = SquarePushPop,
        ["Rotations"] = Rotations,
        ["JointsToolsIO"] = JointsToolsIO,
        ["Print3D"] = Print3D,
    };

    /// <summary>Creates a robot of <paramref name="brand"/> named after the program and issues it.</summary>
    public static Robot Issue(string name, RobotType brand)
    {
        var bot = Robot.Create(name, brand);
        All[name](bot);
        return bot;
    }

    /// <summary>The paper's Code Sample 1.</summary>
    public static void HelloRobot(Robot bot)
    {
        bot.Message("Hello Robot!");
        bot.SpeedTo(100);
        bot.MoveTo(400, 300, 500);
        bot.Rotate(0, 1, 0, -90);
        bot.Move(0, 0, 250);
        bot.Wait(2000);
        bot.AxesTo(0, 0, 0, 0, 90, 0);
    }

    /// <summary>A 50 mm square drawn with temporary settings saved and restored around it.</summary>
    public static void SquarePushPop(Robot bot)
    {
        bot.SpeedTo(50);
        bot.AccelerationTo(500);
        bot.MoveTo(300, 0, 300);
        bot.PushSettings();
        bot.SpeedTo(200);
        bot.PrecisionTo(10);
        bot.AccelerationTo(1000);
        bot.Move(50, 0, 0);
        bot.Move(0, 50, 0);
        bot.Move(-50, 0, 0);
        bot.Move(0, -50, 0);
        bot.PopSettings();
        bot.Move(0, 0, 50);
    }

    /// <summary>Relative rotations in world and tool frames, absolute orientations, and a local move.</summary>
    public static void Rotations(Robot bot)
    {
        bot.MoveTo(300, 200, 400);
        bot.Rotate(0, 0, 1, 45);
        bot.Coordinates("local");
        bot.Rotate(1, 0, 0, 30);
        bot.Move(0, 0, 20);
        bot.Coordinates("world");
        bot.RotateTo(0, 1, 0, 1, 0, 0);
        bot.TransformTo(350, 250, 450, -1, 0, 0, 0, 1, 0);
        bot.Rotate(0, 1, 0, 20);
    }

    /// <summary>Joint moves, a tool with an offset and a rotated tip, digital and analog outputs.</summary>
    public static void JointsToolsIO(Robot bot)
    {
        bot.AxesTo(0, 0, 0, 0, 90, 0);
        bot.MotionMode("joint");
        bot.TransformTo(400, 0, 400, -1, 0, 0, 0, 1, 0);
        bot.DefineTool("pen", 0, 0, 100, 0, 1, 0, -1, 0, 0, 0.5, 0, 0, 50);
        bot.AttachTool("pen");
        bot.MotionMode("linear");
        bot.Move(0, 0, -50);
        bot.WriteDigital(1, true);
        bot.WriteAnalog(2, 0.5);
        bot.Wait(500);
        bot.WriteDigital("DO_Gripper", false, true);
        bot.DetachTool();
        bot.AxesTo(0, -30, 30, 0, 60, 0);
        bot.Axes(10, 0, 0, 0, 0, 0);
    }

    /// <summary>A small 3D print: start-up, heating, two extruded layers of a 20 mm square, shut-down.</summary>
    public static void Print3D(Robot bot)
    {
        bot.Initialize();
        bot.TemperatureTo(60, "bed", false);
        bot.TemperatureTo(210, "extruder", true);
        bot.TemperatureTo(60, "bed", true);
        bot.SpeedTo(30);
        bot.MoveTo(50, 50, 0.3);
        bot.ExtrusionRateTo(0.05);
        bot.Extrude(true);
        for (int layer = 0; layer < 2; layer++)
        {
            bot.Move(20, 0, 0);
            bot.Move(0, 20, 0);
            bot.Move(-20, 0, 0);
            bot.Move(0, -20, 0);
            bot.Move(0, 0, 0.2);
        }
        bot.Extrude(false);
        bot.Move(0, 0, 10);
        bot.Terminate();
    }
}
