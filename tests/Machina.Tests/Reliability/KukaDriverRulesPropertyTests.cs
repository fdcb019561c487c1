using System.Reflection;
using Machina.Simulation;
using Machina.Tests.Online;

namespace Machina.Tests.Reliability;

/// <summary>
/// KUKA's "can the driver run it" (issue 28), through a connected robot as a user meets it: every verb of <see cref="Robot"/>
/// with the edge values of <see cref="ExtremeValues"/> (one parameter at a time) and seeded random combinations. Whatever is
/// issued is executed by the virtual KUKA (never failed, the link never lost); whatever is refused says why
/// (<see cref="ActionRefusedException"/> with a reason) and sends nothing.
/// </summary>
public class KukaDriverRulesPropertyTests
{
    private static readonly TimeSpan Limit = TimeSpan.FromSeconds(20);
    private const string Start = "DefineTool(\"T\", 0, 0, 100, 1, 0, 0, 0, 1, 0, 1, 0, 0, 50); SpeedTo(100); TransformTo(300, 0, 400, -1, 0, 0, 0, 1, 0);";

    [Fact]
    public async Task KukaDriverRules_EdgeAndSeededValuesOfEveryVerb_IssuedAreExecuted_RefusedSayWhy()
    {
        List<(string Name, MethodInfo Verb, object?[] Args)> cases = ExtremeValues.Cases(seed: 3307, seeded: 300);

        // No model: reach is not what this test is about (KukaFailureOnlineTests is); every accepted action must run.
        await using VirtualKukaController controller = await KukaTestSupport.StartKukaAsync(
            // No model: every pose is reachable, so that only the driver's rules decide. The KRL twin moves a real arm's
            // kinematics (a KR 6 R900 sixx without a model), which cannot reach every pose the rules accept.
            new VirtualKukaControllerOptions { Model = null, InstantExecution = true, RequestLogCapacity = 0, RunsKrl = false });
        var problems = new List<string>();
        int issued = 0, refused = 0, skipped = 0;
        (Robot bot, _, _) = await KukaTestSupport.ConnectKukaAsync(controller);
        try
        {
            foreach ((string name, MethodInfo verb, object?[] args) in cases)
            {
                bot.Do(Start);
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
                catch (MachinaException e)
                {
                    // The driver halted (as a KRC does): the rest of the cases would need a fresh controller; one such case is enough to fail.
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
        }

        Assert.True(problems.Count == 0, $"{problems.Count} problems:\n" + string.Join("\n", problems.Take(30)));
        Assert.InRange(cases.Count, 1_000, 100_000);
        Assert.InRange(issued, cases.Count / 5, cases.Count);
        Assert.InRange(refused, cases.Count / 20, cases.Count);
        Assert.Equal(cases.Count, issued + refused + skipped);
    }

    /// <summary>True when every issued action was executed before <paramref name="token"/> fired.</summary>
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
