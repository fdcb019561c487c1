// The paper's "Hello Robot" (Code Sample 1), streamed online to an ABB, UR or KUKA controller.
// With no arguments it starts a virtual ABB controller on this computer (--brand ur: a virtual UR5e; --brand kuka: a
// virtual KR 6 R900 sixx); with --host and --port it talks to a real robot running Machina's driver (see
// Robot.GetDeviceDriverModules; on a UR, Machina sends its URScript driver to the script port, 30003).
// Then it compiles the same seven actions offline for every brand and prints the programs.
using System.Diagnostics;

namespace Machina.Samples;

/// <summary>The Hello Robot sample (the test suite runs it through <see cref="RunAsync"/>).</summary>
public static class HelloRobotSample
{
    /// <summary>Runs the sample: 0 when the seven actions were executed, 1 when the robot link failed, 2 for wrong arguments.</summary>
    public static async Task<int> RunAsync(string[] args, TextWriter output, TextWriter error, CancellationToken cancellationToken)
    {
        await using SampleController? controller = await SampleController.OpenAsync(
            args, "HelloRobot [--brand abb|ur|kuka] [--host <controller address> --port <driver port>]", speedFactor: 4, output, error,
            cancellationToken: cancellationToken);
        if (controller is null)
        {
            return SampleHost.Usage;
        }

        try
        {
            // No model named here: the robot learns its arm's model from the controller when it connects (Machina's drivers and
            // the virtual controllers name it), so it knows the pose after a joint move (forward kinematics) and the joints
            // after a Cartesian one.
            Robot bot = Robot.Create("HelloRobot", controller.Brand);
            bot.ControlMode("online");
            long lastMotion = 0;
            bot.ActionIssued += (_, e) => output.WriteLine($"  issued    #{e.LastAction.Id} {e.LastAction}");
            bot.ActionReleased += (_, e) => output.WriteLine($"  released  #{e.LastAction.Id} ({e.PendingRelease} waiting to be sent)");
            bot.ActionExecuted += (_, e) => output.WriteLine(
                $"  executed  #{e.LastAction.Id} -> position {e.Position?.ToString() ?? "unknown"}, axes {e.Axes?.ToString() ?? "unknown"} ({e.PendingExecutionTotal} left)");
            bot.ConnectionLost += (_, e) => output.WriteLine($"  connection lost: {e.Error.Message}");

            await bot.ConnectAsync(controller.Host, controller.Port, cancellationToken);
            output.WriteLine($"Connected to {bot.GetIP()} ({bot.Model?.Name ?? "arm model unknown"}); the robot is at {bot.GetCurrentPosition()} with axes {bot.GetCurrentAxes()}.");
            // Live poses from the controller's monitor (printed at most every 0.4 s).
            bot.MotionUpdate += (_, e) =>
            {
                if (Stopwatch.GetElapsedTime(lastMotion).TotalMilliseconds >= 400)
                {
                    lastMotion = Stopwatch.GetTimestamp();
                    output.WriteLine($"  moving... tool at {e.Position}");
                }
            };

            HelloRobot(bot);

            using var timeout = CancellationTokenSource.CreateLinkedTokenSource(cancellationToken);
            timeout.CancelAfter(TimeSpan.FromMinutes(2));
            await bot.WaitForCompletionAsync(timeout.Token);
            RobotState final = bot.GetExecutedState();
            output.WriteLine($"Done. Final state: {final}");
            foreach (string refusal in controller.Errors)
            {
                output.WriteLine($"  the virtual controller {refusal}");
            }
            await bot.DisconnectAsync();
        }
        catch (MachinaException ex)
        {
            return SampleHost.LinkFailed(error, ex);
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
                    output.WriteLine();
                    output.WriteLine($"--- {language}: {file.FileName} ---");
                    output.WriteLine(file.ToText());
                }
            }
            catch (NotSupportedException ex)
            {
                output.WriteLine();
                output.WriteLine($"--- {language}: not available in this build ({ex.Message}) ---");
            }
        }
        return SampleHost.Ok;
    }

    // The paper's Code Sample 1.
    private static void HelloRobot(Robot bot)
    {
        bot.Message("Hello Robot!");
        bot.SpeedTo(100);
        bot.MoveTo(400, 300, 500);
        bot.Rotate(0, 1, 0, -90);
        bot.Move(0, 0, 250);
        bot.Wait(2000);
        bot.AxesTo(0, 0, 0, 0, 90, 0);
    }
}
