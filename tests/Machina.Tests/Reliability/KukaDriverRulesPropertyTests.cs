using System.Reflection;
using Machina.Simulation;
using Machina.Tests.Online;

namespace Machina.Tests.Reliability;

/// <summary>
/// KUKA's "can the driver run it" (issue 28), through a connected robot as a user meets it: every verb of <see cref="Robot"/>
/// with the edge values of <see cref="ExtremeValues"/> (one parameter at a time) and seeded random combinations, against the
/// unchanged KRL driver on the twin's KR 6 R900 sixx. Whatever is issued is executed, or fails because the arm cannot get
/// there (the driver's codes 1 and 2: no axis position reaches the target, an axis beyond its software limit switch; the
/// program halts as on a KR C4 and the rest runs on a fresh controller); whatever is refused says why
/// (<see cref="ActionRefusedException"/> with a reason) and sends nothing. Any other failure, or a link lost, is a problem.
/// </summary>
public class KukaDriverRulesPropertyTests
{
    private static readonly TimeSpan Limit = TimeSpan.FromSeconds(60);
    private const string Start = "DefineTool(\"T\", 0, 0, 100, 1, 0, 0, 0, 1, 0, 1, 0, 0, 50); SpeedTo(100); TransformTo(300, 0, 400, -1, 0, 0, 0, 1, 0);";

    [Fact]
    public async Task KukaDriverRules_EdgeAndSeededValuesOfEveryVerb_IssuedAreExecutedOrOutOfReach_RefusedSayWhy()
    {
        List<(string Name, MethodInfo Verb, object?[] Args)> cases = ExtremeValues.Cases(seed: 3307, seeded: 300);
        var problems = new List<string>();
        int issued = 0, refused = 0, skipped = 0, outOfReach = 0;
        VirtualKukaController controller = await StartAsync();
        (Robot bot, _, _) = await KukaTestSupport.ConnectKukaAsync(controller);
        try
        {
            foreach ((string name, MethodInfo verb, object?[] args) in cases)
            {
                bot.Do(Start);
                if (verb.Name == nameof(Robot.WaitForDigital) && InputOf(args[0]) is int pin and >= 1 and <= 4096 && args[1] is bool on)
                {
                    // The input the case waits for is there: its timeout is not what this test is about (KrlDriverTwinTests are).
                    controller.SetDigitalInput(pin, on);
                }
                try
                {
                    verb.Invoke(bot, args);
                    issued++;
                }
                catch (TargetInvocationException e) when (e.InnerException is ActionRefusedException refusal)
                {
                    refused++;
                    if (refusal.Reason.Length < 20)
                    {
                        problems.Add($"{name}: refused without a reason (\"{refusal.Reason}\")");
                    }
                }
                catch (TargetInvocationException e) when (e.InnerException is ArgumentException or InvalidOperationException or NotSupportedException or InstructionParseException)
                {
                    skipped++; // the verb refused its arguments itself (ExtremeValueTests checks how)
                }
                bot.Do("SpeedTo(100); PrecisionTo(0); AccelerationTo(0);");
                // Whatever the case left, the robot must still run a plain move afterwards (a speed that became 0 would not).
                bot.TransformTo(new Vector(300, issued % 2 == 0 ? 10 : -10, 400), Rotation.FlippedAroundY);
                try
                {
                    using var deadline = new CancellationTokenSource(Limit);
                    if (!await CompletesAsync(bot, deadline.Token))
                    {
                        problems.Add($"{name}: not executed within {Limit.TotalSeconds} s; controller errors: {string.Join(" | ", controller.Errors.TakeLast(2))}");
                        break;
                    }
                }
                catch (MachinaException e) when (OutOfReach(e)) // the arm's answer, not the rules: 1 not reachable, 2 software limit switch
                {
                    // The KR 6 cannot get there: the driver halted as a KRC does. The remaining cases run on a fresh controller.
                    outOfReach++;
                    await bot.DisconnectAsync();
                    await controller.DisposeAsync();
                    controller = await StartAsync();
                    (bot, _, _) = await KukaTestSupport.ConnectKukaAsync(controller);
                }
                catch (MachinaException e)
                {
                    problems.Add($"{name}: accepted, but the controller did not run it: {e.Message}");
                    break;
                }
                if (problems.Count > 30)
                {
                    break;
                }
            }
        }
        finally
        {
            await bot.DisconnectAsync();
            await controller.DisposeAsync();
        }

        Assert.True(problems.Count == 0, $"{problems.Count} problems:\n" + string.Join("\n", problems.Take(30)));
        Assert.InRange(cases.Count, 1_000, 100_000);
        Assert.InRange(issued, cases.Count / 5, cases.Count);
        Assert.InRange(refused, cases.Count / 20, cases.Count);
        // Most issued cases run: the arm's reach decides only the far ones.
        Assert.InRange(outOfReach, 0, issued / 2);
        Assert.Equal(cases.Count, issued + refused + skipped);
    }

    /// <summary>The input number a WaitForDigital case names (a number or its text), or null.</summary>
    private static int? InputOf(object? pin) => pin switch
    {
        int number => number,
        string text when int.TryParse(text, System.Globalization.NumberStyles.Integer, System.Globalization.CultureInfo.InvariantCulture, out int number) => number,
        _ => null,
    };

    private static Task<VirtualKukaController> StartAsync() =>
        KukaTestSupport.StartKukaAsync(new VirtualKukaControllerOptions { InstantExecution = true, RequestLogCapacity = 0 });

    /// <summary>True when every issued action was executed before <paramref name="token"/> fired.</summary>
    /// <summary>
    /// The controller refused the case's target as out of reach (code 1) or beyond a software limit (2): as the wait's own failure,
    /// or, when the failure came back before the plain move after the case was issued, as the cause of "stopped after a failure".
    /// </summary>
    private static bool OutOfReach(MachinaException e) =>
        (e as ActionFailedException ?? e.InnerException as ActionFailedException) is { ControllerCode: "1" or "2" };

    private static async Task<bool> CompletesAsync(Robot bot, CancellationToken token)
    {
        try
        {
            await bot.WaitForCompletionAsync(token);
            return true;
        }
        catch (OperationCanceledException) when (token.IsCancellationRequested)
        {
            return false;
        }
    }
}
