#if MACHINA_ONLINE
using System.Diagnostics;

namespace Machina.Benchmarks;

/// <summary>
/// <c>--restarts N</c>: the restart schedule of the fault matrix (<see cref="RestartTrial"/>), N seeded trials per brand (seeds
/// 40000 on), one after the other, with the default policy (unknown outcomes are not sent again) or, with
/// <c>--resend</c>, <c>ResendAfterControllerRestart</c>; <c>--brand</c> picks brands (all three by default). Prints one line
/// per brand: actions run twice on the controller (its own log), actions not sent again (the host's failures) and actions that
/// never ended; exit code 1 when the default policy ran anything twice, or any action never ended, or a trial could not end.
/// </summary>
internal static class RestartRun
{
    /// <summary>The first seed; trial i uses FirstSeed + i.</summary>
    public const int FirstSeed = 40000;

    public static int Run(int trials, bool resend, IReadOnlyList<string> brands)
    {
        bool ok = true;
        Console.WriteLine($"Restart schedule: {trials} trials per brand, seeds {FirstSeed}-{FirstSeed + trials - 1}, "
            + (resend ? "ResendAfterControllerRestart = true" : "default policy (not sent again)"));
        Console.WriteLine("brand | trials | run twice (actions, trials) | not sent again (actions, trials) | never ended | trials failed | recoveries | time");
        foreach (string brand in RestartTrial.Brands.Where(b => brands.Count == 0 || brands.Contains(b, StringComparer.OrdinalIgnoreCase)))
        {
            int twice = 0, twiceTrials = 0, notResent = 0, notResentTrials = 0, unended = 0, failedTrials = 0, recoveries = 0;
            var clock = Stopwatch.StartNew();
            for (int i = 0; i < trials; i++)
            {
                int seed = FirstSeed + i;
                try
                {
                    RestartTrial.Result r = RestartTrial.RunAsync(brand, seed, resend ? b => b.ResendAfterControllerRestart = true : null, TimeSpan.FromSeconds(30))
                        .GetAwaiter().GetResult();
                    twice += r.RunTwice.Count;
                    twiceTrials += r.RunTwice.Count > 0 ? 1 : 0;
                    notResent += r.Failed.Count;
                    notResentTrials += r.Failed.Count > 0 ? 1 : 0;
                    unended += r.Unended.Count;
                    recoveries += r.Recoveries;
                    if ((!resend && r.RunTwice.Count > 0) || r.Unended.Count > 0)
                    {
                        Console.Error.WriteLine(r.Describe());
                    }
                }
                catch (RestartTrial.TrialException e)
                {
                    failedTrials++;
                    Console.Error.WriteLine(e.Message);
                }
            }
            Console.WriteLine($"{brand} | {trials} | {twice}, {twiceTrials} | {notResent}, {notResentTrials} | {unended} | {failedTrials} | {recoveries} | {clock.Elapsed.TotalSeconds:0.0} s");
            ok &= (resend || twice == 0) && unended == 0 && failedTrials == 0;
        }
        return ok ? 0 : 1;
    }
}
#endif
