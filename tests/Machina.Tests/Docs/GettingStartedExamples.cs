using Machina;
using Machina.Simulation;

namespace Machina.Tests.Docs;

/// <summary>
/// The C# snippets of docs/getting-started.md, one method per snippet, named after its marker (&lt;!-- checked: Name --&gt;).
/// <see cref="GettingStartedDocTests"/> checks that each body is the snippet printed (after its using lines, which must be
/// the usings of this file) and runs the ones that need no real robot. The parameter named <c>Console</c> lets a snippet
/// print with <c>Console.WriteLine</c> while the test reads what it printed.
/// </summary>
internal static class GettingStartedExamples
{
    internal static void FirstOfflineProgram(TextWriter Console)
    {
        var bot = Robot.Create("FirstProgram", "ABB");   // or "UR", "KUKA", "ZMORPH", "MARLIN"
        bot.SpeedTo(50);                                 // mm/s
        bot.MoveTo(300, 0, 400);                         // mm, absolute: where the tool tip goes
        bot.Move(0, 100, 0);                             // mm, relative: 100 mm along Y
        bot.Wait(1000);                                  // ms
        bot.AxesTo(0, 0, 0, 0, 90, 0);                   // joint angles, degrees

        RobotProgram program = bot.Compile();
        Console.WriteLine(program.MainFile.ToText());
        bot.SaveProgram(program, "programs");            // programs/FirstProgram_Program/FirstProgram.mod and .pgf
    }

    internal static async Task FirstVirtualRobot(TextWriter Console)
    {
        // A virtual ABB IRB 120 on this computer, running 10 times faster than real time.
        await using var controller = new VirtualAbbController(new VirtualAbbControllerOptions { SpeedFactor = 10 });
        await controller.StartAsync();

        await using var bot = Robot.Create("FirstVirtualRobot", "ABB", "IRB 120");
        bot.ActionIssued += (_, e) => Console.WriteLine($"issued   #{e.LastAction.Id} {e.LastAction}");
        bot.ActionReleased += (_, e) => Console.WriteLine($"released #{e.LastAction.Id}");
        bot.ActionExecuted += (_, e) => Console.WriteLine($"executed #{e.LastAction.Id}: the tool is at {e.Position}");

        bot.ControlMode("online");
        await bot.ConnectAsync("127.0.0.1", controller.Port);
        Console.WriteLine($"Connected: the tool is at {bot.GetCurrentPosition()}");

        bot.SpeedTo(100);
        bot.MoveTo(300, 100, 400);
        bot.Move(0, 0, -100);
        bot.Wait(500);
        bot.AxesTo(0, 0, 0, 0, 90, 0);

        await bot.WaitForCompletionAsync();
        Console.WriteLine($"Done: the joints are at {bot.GetCurrentAxes()}");
        await bot.DisconnectAsync();
    }

    internal static async Task FirstRealRobot(TextWriter Console)
    {
        await using var bot = Robot.Create("FirstRealRobot", "ABB", "IRB 120");   // your brand and model
        bot.StrictMode(true);                      // refuse (not just warn about) motions the arm cannot make
        bot.ControlMode("online");
        await bot.ConnectAsync("192.168.125.1", 7000);   // the controller's address and the driver's port
        Console.WriteLine($"The tool is at {bot.GetCurrentPosition()}, the joints at {bot.GetCurrentAxes()}");

        bot.SpeedTo(20);                           // slow: 20 mm/s
        bot.Move(0, 0, 20);                        // a small move up, away from anything below the tool
        bot.Move(0, 0, -20);                       // and back
        await bot.WaitForCompletionAsync();
        await bot.DisconnectAsync();
    }
}
