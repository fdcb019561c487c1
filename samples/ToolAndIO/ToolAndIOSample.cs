// A tool and the controller's outputs: define a gripper (where its tip is, how heavy it is, where its weight sits), attach it,
// move with it, switch a digital output (e.g. the gripper's valve) and set an analog one (e.g. a pressure or a spindle
// speed), wait, and detach it. The same program is compiled for ABB, UR and KUKA and printed, then streamed online to a
// virtual controller (ABB by default; --brand ur or --brand kuka), which reports the tool and the outputs it has set.
//
// Usage: dotnet run --project samples/ToolAndIO [--brand abb|ur|kuka] [--host <controller address> --port <driver port>]
//
// Outputs are named differently per brand: ABB signals have names given in the controller's IO configuration (here DO_1
// and AO_1, change them to yours); UR and KUKA outputs are numbered (digital 1, analog 1). KUKA analog outputs take -1 to
// 1, UR's 0 to 1: 0.5 suits both.
namespace Machina.Samples;

/// <summary>The tool and IO sample (the test suite runs it through <see cref="RunAsync"/>).</summary>
public static class ToolAndIOSample
{
    /// <summary>Runs the sample: 0 when the controller set the outputs as programmed, 1 when not (or the link failed), 2 for wrong arguments.</summary>
    public static async Task<int> RunAsync(string[] args, TextWriter output, TextWriter error, CancellationToken cancellationToken)
    {
        await using SampleController? controller = await SampleController.OpenAsync(
            args, "ToolAndIO [--brand abb|ur|kuka] [--host <controller address> --port <driver port>]", speedFactor: 4, output, error,
            cancellationToken: cancellationToken);
        if (controller is null)
        {
            return SampleHost.Usage;
        }

        // 1. Offline: the same program in each robot language.
        foreach (RobotType brand in new[] { RobotType.ABB, RobotType.UR, RobotType.KUKA })
        {
            var offline = Robot.Create("ToolAndIO", brand);
            offline.MoveTo(400, 0, 400);   // a known start, so that every language writes full targets
            DefineAndAttach(offline);
            SwitchOn(offline, brand);
            SwitchOffAndDetach(offline, brand);
            RobotProgram program = offline.Compile();
            output.WriteLine($"--- {brand}: the tool and IO lines of {program.MainFile.FileName} ---");
            foreach (string line in program.MainFile.Lines.Where(IsToolOrIO))
            {
                output.WriteLine("  " + line.Trim());
            }
            foreach (ProgramWarning warning in program.Warnings)
            {
                output.WriteLine($"  warning: {warning}");
            }
        }

        // 2. Online: stream it to the controller and watch each action's life.
        output.WriteLine();
        try
        {
            var bot = Robot.Create("ToolAndIO", controller.Brand);
            RobotType online = bot.Brand;
            bot.ControlMode("online");
            bot.ActionIssued += (_, e) => output.WriteLine($"  issued    #{e.LastAction.Id} {e.LastAction.ToInstruction()}");
            bot.ActionReleased += (_, e) => output.WriteLine($"  released  #{e.LastAction.Id}");
            bot.ActionExecuted += (_, e) => output.WriteLine($"  executed  #{e.LastAction.Id} ({e.PendingExecutionTotal} left)");
            await bot.ConnectAsync(controller.Host, controller.Port, cancellationToken);
            output.WriteLine($"Connected to the {online} controller at {bot.GetIP()}; the tool tip is at {bot.GetCurrentPosition()}.");

            DefineAndAttach(bot);
            SwitchOn(bot, online);
            await WaitAsync(bot, cancellationToken);
            output.WriteLine($"With the tool attached and the outputs on, the controller reports: {Report(controller, online)}");
            bool onAsProgrammed = controller.State is not { } on || IsSet(on, online, true, 0.5);

            SwitchOffAndDetach(bot, online);
            await WaitAsync(bot, cancellationToken);
            output.WriteLine($"After switching off and detaching, the controller reports: {Report(controller, online)}");
            bool offAsProgrammed = controller.State is not { } off || IsSet(off, online, false, 0) && off.Tool is null;
            foreach (string refusal in controller.Errors)
            {
                output.WriteLine($"  the virtual controller {refusal}");
            }
            await bot.DisconnectAsync();

            if (!onAsProgrammed || !offAsProgrammed || controller.Errors.Count > 0)
            {
                return SampleHost.Fail(error, "the virtual controller did not set the tool and the outputs as programmed (see above).");
            }
            return SampleHost.Ok;
        }
        catch (MachinaException ex)
        {
            return SampleHost.LinkFailed(error, ex);
        }
    }

    /// <summary>A gripper 120 mm long (its tip straight out of the flange), 1.2 kg, its weight 50 mm out from the flange.</summary>
    private static void DefineAndAttach(Robot bot)
    {
        bot.DefineTool("gripper",
            0, 0, 120,        // the tip, mm from the flange
            1, 0, 0,          // the tip's X axis: as the flange's
            0, 1, 0,          // the tip's Y axis: as the flange's
            1.2,              // weight, kg: the controller needs it to move the arm safely
            0, 0, 50);        // centre of gravity, mm from the flange
        bot.AttachTool("gripper");   // from now on, positions are those of the gripper's tip
        bot.SpeedTo(50);
        bot.Move(0, 0, -50);         // down 50 mm
    }

    private static void SwitchOn(Robot bot, RobotType brand)
    {
        bot.WriteDigital(DigitalOutput(brand), true);   // e.g. close the gripper
        bot.WriteAnalog(AnalogOutput(brand), 0.5);      // e.g. half pressure
        bot.Wait(500);                                  // give it half a second
    }

    private static void SwitchOffAndDetach(Robot bot, RobotType brand)
    {
        bot.Move(0, 0, 50);                             // up again
        bot.WriteDigital(DigitalOutput(brand), false);
        bot.WriteAnalog(AnalogOutput(brand), 0);
        bot.DetachTool();                               // positions are those of the flange again
    }

    private static string DigitalOutput(RobotType brand) => brand == RobotType.ABB ? "DO_1" : "1";

    private static string AnalogOutput(RobotType brand) => brand == RobotType.ABB ? "AO_1" : "1";

    private static async Task WaitAsync(Robot bot, CancellationToken cancellationToken)
    {
        using var timeout = CancellationTokenSource.CreateLinkedTokenSource(cancellationToken);
        timeout.CancelAfter(TimeSpan.FromMinutes(1));
        await bot.WaitForCompletionAsync(timeout.Token);
    }

    /// <summary>The lines about the gripper, the outputs and the wait (Machina's comments name each action).</summary>
    private static bool IsToolOrIO(string line) =>
        new[] { "gripper", "Detach all tools", "digital IO", "analog IO", "[Wait", "load data" }.Any(word => line.Contains(word, StringComparison.Ordinal));

    private static bool IsSet(Machina.Simulation.VirtualRobotState state, RobotType brand, bool digital, double analog) =>
        // An output a controller does not list is off (0): the virtual UR lists only the outputs that are on.
        state.DigitalOutputs.GetValueOrDefault(DigitalOutput(brand)) == digital
        && Math.Abs(state.AnalogOutputs.GetValueOrDefault(AnalogOutput(brand)) - analog) < 1e-6;

    /// <summary>
    /// The tool and the outputs this sample uses as the virtual controller has them (nothing for a real controller: look at its
    /// pendant). An output the controller does not list is off (0): the virtual UR lists only the outputs that are on.
    /// </summary>
    private static string Report(SampleController controller, RobotType brand)
    {
        if (controller.State is not { } state)
        {
            return "(a real controller: see its pendant)";
        }
        string tool = state.Tool is { } t ? $"tool tip at {t.Position} from the flange" : "no tool";
        bool digital = state.DigitalOutputs.GetValueOrDefault(DigitalOutput(brand));
        double analog = state.AnalogOutputs.GetValueOrDefault(AnalogOutput(brand));
        return $"{tool}; digital outputs: {DigitalOutput(brand)} = {(digital ? "on" : "off")}; analog outputs: {AnalogOutput(brand)} = {analog:0.###}.";
    }
}
