// The paper's "Hello Robot" (Code Sample 1), streamed online to an ABB, UR or KUKA controller.
// With no arguments it starts a virtual ABB controller on this computer (--brand ur: a virtual UR5e; --brand kuka: a
// virtual KR 6 R900 sixx); with --host and --port it talks to a real robot running Machina's driver (see
// Robot.GetDeviceDriverModules; on a UR, Machina sends its URScript driver to the script port, 30003).
using System.Diagnostics;
using Machina;

await using SampleController? controller = await SampleController.OpenAsync(
    args, "HelloRobot [--brand abb|kuka] [--host <controller address> --port <driver port>]", speedFactor: 4);
if (controller is null)
{
    return 2;
}

try
{
    var bot = Robot.Create("HelloRobot", controller.Brand);
    bot.ControlMode("online");
    long lastMotion = 0;
    bot.ActionIssued += (_, e) => Console.WriteLine($"  issued    #{e.LastAction.Id} {e.LastAction}");
    bot.ActionReleased += (_, e) => Console.WriteLine($"  released  #{e.LastAction.Id} ({e.PendingRelease} waiting to be sent)");
    bot.ActionExecuted += (_, e) => Console.WriteLine(
        $"  executed  #{e.LastAction.Id} -> position {e.Position?.ToString() ?? "unknown"}, axes {e.Axes?.ToString() ?? "unknown"} ({e.PendingExecutionTotal} left)");
    bot.ConnectionLost += (_, e) => Console.WriteLine($"  connection lost: {e.Error.Message}");

    await bot.ConnectAsync(controller.Host, controller.Port);
    Console.WriteLine($"Connected to {bot.GetIP()}; the robot is at {bot.GetCurrentPosition()} with axes {bot.GetCurrentAxes()}.");
    // Live poses from the controller's monitor (printed at most every 0.4 s).
    bot.MotionUpdate += (_, e) =>
    {
        if (Stopwatch.GetElapsedTime(lastMotion).TotalMilliseconds >= 400)
        {
            lastMotion = Stopwatch.GetTimestamp();
            Console.WriteLine($"  moving... tool at {e.Position}");
        }
    };

    HelloRobot(bot);

    using var timeout = new CancellationTokenSource(TimeSpan.FromMinutes(2));
    await bot.WaitForCompletionAsync(timeout.Token);
    RobotState final = bot.GetExecutedState();
    Console.WriteLine($"Done. Final state: {final}");
    foreach (string error in controller.Errors)
    {
        Console.WriteLine($"  the virtual controller {error}");
    }
    await bot.DisconnectAsync();
}
catch (MachinaException ex)
{
    Console.Error.WriteLine($"The robot link failed: {ex.Message}");
    return 1;
}

// The same actions, compiled offline for every brand this build knows.
var offline = Robot.Create("HelloRobot", "ABB");
HelloRobot(offline);
foreach (RobotType language in new[] { RobotType.ABB, RobotType.UR, RobotType.KUKA, RobotType.HUMAN })
{
    try
    {
        RobotProgram program = offline.Compile(language);
        foreach (RobotProgramFile file in program.Files)
        {
            Console.WriteLine();
            Console.WriteLine($"--- {language}: {file.FileName} ---");
            Console.WriteLine(file.ToText());
        }
    }
    catch (NotSupportedException ex)
    {
        Console.WriteLine();
        Console.WriteLine($"--- {language}: not available in this build ({ex.Message}) ---");
    }
}
return 0;

// The paper's Code Sample 1.
static void HelloRobot(Robot bot)
{
    bot.Message("Hello Robot!");
    bot.SpeedTo(100);
    bot.MoveTo(400, 300, 500);
    bot.Rotate(0, 1, 0, -90);
    bot.Move(0, 0, 250);
    bot.Wait(2000);
    bot.AxesTo(0, 0, 0, 0, 90, 0);
}
