using System.Text.RegularExpressions;
using Machina.Benchmarks;
using Machina.Simulation;
using Xunit.Abstractions;
using static Machina.Tests.Online.OnlineTestSupport;

namespace Machina.Tests.Reliability;

/// <summary>
/// The restart schedule of the fault matrix (issue 40), for every brand: the controller restarts mid-stream losing its
/// program, buffer and progress (<see cref="VirtualFault.RestartLosingProgress"/> after a seeded acknowledgement, with a seeded
/// release window), and the host connects again. By default nothing runs twice on the controller (its own execution log):
/// the actions whose outcome is unknown end failed with the reason, are reported at WARNING with their ids, and the wait after
/// the restart throws; the actions never sent run once. With <c>ResendAfterControllerRestart</c> they are sent again and every
/// action ends executed. The 200-trial run per brand is a benchmark command (docs/reliability.md, "Controller restarts").
/// </summary>
public class ControllerRestartTests(ITestOutputHelper output)
{
    private const string Reason = "the controller restarted; this action may or may not have run";

    public static TheoryData<string, int> Seeds()
    {
        var data = new TheoryData<string, int>();
        foreach (string brand in (string[])["ABB", "UR", "KUKA"])
        {
            foreach (int seed in (int[])[40001, 40002, 40003])
            {
                data.Add(brand, seed);
            }
        }
        return data;
    }

    [Theory]
    [MemberData(nameof(Seeds))]
    public async Task Restart_ByDefault_NothingRunsTwice_UnknownOutcomesFailAndAreReported(string brand, int seed)
    {
        RestartTrial.Result r = await RestartTrial.RunAsync(brand, seed, null, Limit);
        output.WriteLine(r.Describe());

        Assert.True(r.RunTwice.Count == 0, $"{r.RunTwice.Count} actions ran twice on the controller: {string.Join(' ', r.RunTwice)}");
        Assert.Equal([VirtualFault.RestartLosingProgress], r.Injected);
        Assert.Equal(1, r.Recoveries);
        Assert.Empty(r.ControllerErrors);
        Assert.Equal(0, r.Pending);

        // Every action ended once: executed (and then it ran on the controller) or failed, never both.
        List<int> failed = [.. r.Failed.Select(f => f.Action.Id)];
        Assert.Empty(r.Unended);
        Assert.Empty(r.Executed.Intersect(failed));
        Assert.Equal(r.Executed.Order(), r.Executed);
        Assert.Equal(r.Executed.Distinct().Count(), r.Executed.Count);
        Assert.Empty(r.Executed.Except(r.ControllerLog));
        Assert.NotEmpty(failed); // the seeds are chosen so that actions are in flight at the restart
        int first = failed[0];
        Assert.Equal(Enumerable.Range(first, failed.Count), failed); // those released after the last acknowledgement seen
        Assert.Equal(Enumerable.Range(1, first - 1), r.Executed.Take(first - 1));
        Assert.Equal(Enumerable.Range(first + failed.Count, RestartTrial.Actions - first - failed.Count + 1), r.Executed.Skip(first - 1));
        foreach (ActionFailedArgs f in r.Failed)
        {
            Assert.Equal(Reason, f.Reason);
            Assert.Equal("restarted", f.Failure.ControllerCode);
            Assert.Empty(f.CancelledActions);
        }

        // Reported: one warning with the count and the ids, and the wait after the restart throws once.
        string warning = Assert.Single(r.Warnings, w => w.StartsWith("The controller restarted", StringComparison.Ordinal));
        Assert.Contains($"{failed.Count} actions sent before the restart", warning, StringComparison.Ordinal);
        Assert.Equal(failed, IdsIn(warning));
        Assert.Contains("not sent again", warning, StringComparison.Ordinal);
        ActionFailedException thrown = Assert.IsType<ActionFailedException>(Assert.Single(r.WaitFailures));
        Assert.Equal(first, thrown.Action.Id);
        Assert.Equal(Reason, thrown.ControllerReason);
        // How many were in flight depends on how far the host had read when the restart came: one is named on its own.
        Assert.Contains(failed.Count == 1 ? $"(id {first}) was not sent again" : $"{failed.Count} actions", thrown.Message, StringComparison.Ordinal);

        Assert.True(r.ControllerPosition.IsSimilar(r.ExecutedPosition, 1e-6), $"the arm is at {r.ControllerPosition}, the host says {r.ExecutedPosition}");
    }

    [Theory]
    [InlineData("ABB", 40001)]
    [InlineData("UR", 40001)]
    [InlineData("KUKA", 40001)]
    public async Task Restart_ResendPolicy_UnknownOutcomesSentAgain_EveryActionExecuted(string brand, int seed)
    {
        RestartTrial.Result r = await RestartTrial.RunAsync(brand, seed, b => b.ResendAfterControllerRestart = true, Limit);
        output.WriteLine(r.Describe());

        Assert.Equal([VirtualFault.RestartLosingProgress], r.Injected);
        Assert.Equal(Enumerable.Range(1, RestartTrial.Actions), r.Executed);
        Assert.Empty(r.Failed);
        Assert.Empty(r.WaitFailures);
        Assert.Equal(0, r.Pending);
        Assert.Empty(Enumerable.Range(1, RestartTrial.Actions).Except(r.ControllerLog));
        string warning = Assert.Single(r.Warnings, w => w.StartsWith("The controller restarted", StringComparison.Ordinal));
        Assert.Contains("are sent again (ResendAfterControllerRestart)", warning, StringComparison.Ordinal);
        List<int> resent = IdsIn(warning);
        Assert.NotEmpty(resent);
        Assert.Empty(r.RunTwice.Except(resent)); // only a resent action may have run twice
        Assert.True(r.ControllerPosition.IsSimilar(r.ExecutedPosition, 1e-6), $"the arm is at {r.ControllerPosition}, the host says {r.ExecutedPosition}");
    }

    /// <summary>The ids a warning lists, "(ids 12-18, 20)", in order.</summary>
    private static List<int> IdsIn(string warning)
    {
        Match m = Regex.Match(warning, @"\(ids? ([0-9, -]+)\)");
        Assert.True(m.Success, "no ids in: " + warning);
        var ids = new List<int>();
        foreach (string part in m.Groups[1].Value.Split(", "))
        {
            string[] ends = part.Split('-');
            int from = int.Parse(ends[0], Num.Inv), to = int.Parse(ends[^1], Num.Inv);
            ids.AddRange(Enumerable.Range(from, to - from + 1));
        }
        return ids;
    }
}
