#if MACHINA_ONLINE
using System.Globalization;

namespace Machina.Benchmarks;

/// <summary>
/// <c>--rtde-rate --process</c>: the RTDE rate with each party in a process of its own, so that no garbage collection of the
/// host or the client stops the twin's sender (in <c>--rtde-rate</c> the three share one process and its pauses). The twin is
/// <c>machina sim ur --port 0 --quiet --speed-factor 1000</c> (the native tool with --native PATH, else the JIT tool built
/// beside the benchmarks), the stream's host is this program as a child (<c>--child stream brand=UR</c>, <c>--size</c> moves,
/// default 10^5), and the reading client is the one of <see cref="RtdeRateRun"/>, here. --child-env variables go to the twin and
/// the host (e.g. DOTNET_gcServer=1). A fresh twin per row.
/// </summary>
internal static class RtdeRateApartRun
{
    public static int Run(int? streamSize, string? native)
    {
        int actions = streamSize ?? 100_000;
        string twin = native ?? Path.Combine(AppContext.BaseDirectory, "Machina.Cli");
        string environment = ChildProcess.Environment.Count == 0 ? "none" : string.Join(" ", ChildProcess.Environment.Select(p => $"{p.Key}={p.Value}"));
        Console.WriteLine($"RTDE output rate of the virtual UR, each in its own process: twin {twin} (sim ur, 1000x), host a child streaming {actions:N0} moves, reader here");
        Console.WriteLine($"child environment: {environment}; reader thread's slice: {(RtdeRateRun.ReaderSlice ? "100 us" : "the system's")}; load average {Machine.LoadAverage()} at start");
        Console.WriteLine();
        Console.WriteLine("| asked (Hz) | beside | delivered (Hz) | period error p50 (ms) | p99 (ms) | max (ms) | packages | twin cpu (ms/s) | reader GCs (pause ms) | load average | target |");
        Console.WriteLine("|---|---|---|---|---|---|---|---|---|---|---|");
        bool met = true;
        foreach (double asked in new double[] { 125, 500 })
        {
            foreach (bool stream in new[] { false, true })
            {
                TwinsSideBySideRun.Twin sim = TwinsSideBySideRun.Start(twin, "ur");
                try
                {
                    double cpuBefore = TwinsSideBySideRun.ProcessorSeconds(sim.Process.Id);
                    long start = System.Diagnostics.Stopwatch.GetTimestamp();
                    RtdeRateRun.Row row = RtdeRateRun.Measure(sim.Port + 1, asked, stream ? () => Stream(sim.Port, actions) : null);
                    double cpu = (TwinsSideBySideRun.ProcessorSeconds(sim.Process.Id) - cpuBefore) / System.Diagnostics.Stopwatch.GetElapsedTime(start).TotalSeconds * 1000;
                    string target = row.Target(asked);
                    met &= target != "missed";
                    Console.WriteLine(string.Create(CultureInfo.InvariantCulture,
                        $"| {asked:0} | {(stream ? $"{actions:N0} moves" : "nothing")} | {row.Delivered:0.0} | {row.P50:0.000} | {row.P99:0.000} | {row.Max:0.000} | {row.Packages} | {cpu:0} | {row.Collections} ({row.GcPause.TotalMilliseconds:0.0}) | {Machine.LoadAverage()} | {target} |"));
                }
                finally
                {
                    TwinsSideBySideRun.Stop(sim);
                }
            }
        }
        Console.WriteLine();
        Console.WriteLine($"500 Hz target (>= {RtdeRateRun.MinDelivered500} Hz delivered, p99 period error <= {RtdeRateRun.MaxP99Error} ms): {(met ? "met" : "missed")}");
        return 0;
    }

    /// <summary>The host in a child process: connects to the twin's script port, streams, waits until every move is done.</summary>
    private static void Stream(int port, int actions) => ChildProcess.Run(
        ["stream", "port=" + port.ToString(CultureInfo.InvariantCulture), "count=" + actions.ToString(CultureInfo.InvariantCulture), "brand=UR"],
        TimeSpan.FromMinutes(5) + TimeSpan.FromMilliseconds(actions));
}
#endif
