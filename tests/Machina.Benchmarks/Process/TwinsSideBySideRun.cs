#if MACHINA_ONLINE
using System.Diagnostics;
using System.Globalization;
using System.Text.RegularExpressions;

namespace Machina.Benchmarks;

/// <summary>
/// <c>--twins N</c>: issue 45's "twins as cheap as processes can be". Starts N native twins (<c>machina sim BRAND --port 0
/// --quiet --speed-factor 1000</c>) side by side, each its own process, and records how long each took to listen and its
/// resident memory once listening; then N hosts in this process, one robot per twin, each streams <c>--size</c> moves
/// (default 10,000) at once with the default window. Prints one row per brand: ready times, memory, each host's
/// rate (slowest and median), and the processor time of every process together per action. Targets: ready ≤ 100 ms,
/// ≤ 32 MB each, every host ≥ 1,000 actions/s.
/// </summary>
internal static partial class TwinsSideBySideRun
{
    private const double ReadyTargetMs = 100, MemoryTargetMb = 32, RateTarget = 1000;

    public static int Run(int twins, int? size, IReadOnlyList<string> brands)
    {
        int moves = size ?? 10_000;
        string native = ExternalToolScenario.Native();
        string[] selected = brands.Count == 0 ? ["abb", "ur", "kuka"] : [.. brands.Select(b => b.ToLowerInvariant())];
        Console.WriteLine($"{twins} native twins side by side ({native}), each serving its own host (in this process) {moves:N0} moves");
        Console.WriteLine($"load average {Machine.LoadAverage()} at start");
        Console.WriteLine();
        Console.WriteLine("| brand | twins | ready p50 / max (ms) | resident p50 / max once ready (MB) | peak resident max (MB) | host rate slowest / median (actions/s) | all processes' cpu per action | load average | status |");
        Console.WriteLine("|---|---:|---:|---:|---:|---:|---:|---:|---|");
        bool met = true;
        foreach (string brand in selected)
        {
            Row row = Measure(native, brand, twins, moves);
            bool ok = row.ReadyMax <= ReadyTargetMs && row.MemoryMax <= MemoryTargetMb && row.RateMin >= RateTarget;
            met &= ok;
            Console.WriteLine(string.Create(CultureInfo.InvariantCulture,
                $"| {brand} | {twins} | {row.ReadyP50:0} / {row.ReadyMax:0} | {row.MemoryP50:0.0} / {row.MemoryMax:0.0} | {row.PeakMax:0.0} | {row.RateMin:N0} / {row.RateP50:N0} | {row.CpuPerAction:0.0} µs | {Machine.LoadAverage()} | {(ok ? "met" : "missed")} |"));
        }
        Console.WriteLine();
        Console.WriteLine($"targets (ready <= {ReadyTargetMs} ms, <= {MemoryTargetMb} MB each, every host >= {RateTarget:N0} actions/s): {(met ? "met" : "missed")}");
        return 0;
    }

    private sealed record Row(double ReadyP50, double ReadyMax, double MemoryP50, double MemoryMax, double PeakMax, double RateMin, double RateP50, double CpuPerAction);

    internal sealed record Twin(Process Process, int Port, double ReadyMs, double ResidentMb);

    [GeneratedRegex(@"listening on 127\.0\.0\.1:(\d+)")]
    private static partial Regex Listening();

    private static Row Measure(string native, string brand, int count, int moves)
    {
        var twins = new List<Twin>();
        try
        {
            // One at a time, as a user starts them: each twin's ready time is its own, not a queue behind the others.
            for (int i = 0; i < count; i++)
            {
                twins.Add(Start(native, brand));
            }
            double cpuBefore = twins.Sum(t => ProcessorSeconds(t.Process.Id)) + ProcessorSeconds(Environment.ProcessId);
            var robotType = Enum.Parse<RobotType>(brand, ignoreCase: true);
            Task<double>[] hosts = [.. twins.Select(t => Task.Run(() => Host(robotType, t.Port, moves)))];
            Task.WaitAll(hosts);
            double cpuAfter = twins.Sum(t => ProcessorSeconds(t.Process.Id)) + ProcessorSeconds(Environment.ProcessId);
            double[] rates = [.. hosts.Select(h => h.Result).Order()];
            double[] ready = [.. twins.Select(t => t.ReadyMs).Order()];
            double[] memory = [.. twins.Select(t => t.ResidentMb).Order()];
            double peak = twins.Max(t => StatusMb(t.Process.Id, "VmHWM:"));
            return new Row(ready[ready.Length / 2], ready[^1], memory[memory.Length / 2], memory[^1], peak, rates[0], rates[rates.Length / 2],
                (cpuAfter - cpuBefore) / ((double)count * moves) * 1e6);
        }
        finally
        {
            twins.ForEach(Stop);
        }
    }

    /// <summary>Starts <c>machina sim BRAND --port 0 --quiet --speed-factor 1000</c> (with --child-env's variables) and waits until it says where it listens.</summary>
    internal static Twin Start(string native, string brand)
    {
        var info = new ProcessStartInfo(native) { RedirectStandardOutput = true, RedirectStandardError = true, UseShellExecute = false };
        foreach (string argument in (string[])["sim", brand, "--port", "0", "--quiet", "--speed-factor", "1000"])
        {
            info.ArgumentList.Add(argument);
        }
        foreach ((string key, string value) in ChildProcess.Environment)
        {
            info.Environment[key] = value;
        }
        long start = Stopwatch.GetTimestamp();
        var process = Process.Start(info) ?? throw new InvalidOperationException($"{native} did not start.");
        process.ErrorDataReceived += (_, _) => { };
        process.BeginErrorReadLine();
        // Bounded: a twin that says nothing for 10 s is a failure of the run, not a hang.
        Task<string?> first = process.StandardOutput.ReadLineAsync();
        if (!first.Wait(TimeSpan.FromSeconds(10)) || first.Result is not { } line || Listening().Match(line) is not { Success: true } match)
        {
            process.Kill(entireProcessTree: true);
            throw new InvalidOperationException($"The {brand} twin did not say where it listens within 10 s.");
        }
        double readyMs = Stopwatch.GetElapsedTime(start).TotalMilliseconds;
        // The rest of its output is drained so that it never blocks on a full pipe.
        _ = process.StandardOutput.BaseStream.CopyToAsync(Stream.Null);
        return new Twin(process, int.Parse(match.Groups[1].Value, CultureInfo.InvariantCulture), readyMs, StatusMb(process.Id, "VmRSS:"));
    }

    /// <summary>Ends a twin's process (and waits a little for it), whether it is still running or not.</summary>
    internal static void Stop(Twin twin)
    {
        try
        {
            twin.Process.Kill(entireProcessTree: true);
            twin.Process.WaitForExit(5000);
        }
        catch (InvalidOperationException)
        {
            // Already gone.
        }
        twin.Process.Dispose();
    }

    /// <summary>One host: connect, SpeedTo(200), <paramref name="moves"/> moves of ±1 mm, wait; returns its actions per second from the first move.</summary>
    private static double Host(RobotType brand, int port, int moves)
    {
        var bot = Robot.Create("Side" + port, brand.ToString());
        try
        {
            bot.ControlMode("online");
            using var connect = new CancellationTokenSource(TimeSpan.FromSeconds(30));
            bot.ConnectAsync("127.0.0.1", port, connect.Token).GetAwaiter().GetResult();
            long start = Stopwatch.GetTimestamp();
            bot.SpeedTo(200);
            Vector right = new(1, 0, 0), left = new(-1, 0, 0);
            for (int i = 0; i < moves; i++)
            {
                bot.Move((i & 1) == 0 ? right : left);
            }
            using var timeout = new CancellationTokenSource(TimeSpan.FromMinutes(2) + TimeSpan.FromMilliseconds(moves));
            bot.WaitForCompletionAsync(timeout.Token).GetAwaiter().GetResult();
            return moves / Stopwatch.GetElapsedTime(start).TotalSeconds;
        }
        finally
        {
            bot.DisconnectAsync().GetAwaiter().GetResult();
        }
    }

    /// <summary>User + system processor seconds of a process so far (/proc/PID/stat, 100 ticks a second), 0 when it is gone.</summary>
    internal static double ProcessorSeconds(int pid) => Machine.StatFields($"/proc/{pid}/stat") is { } fields
        ? (long.Parse(fields[11], CultureInfo.InvariantCulture) + long.Parse(fields[12], CultureInfo.InvariantCulture)) / 100.0
        : 0;

    /// <summary>A memory line of /proc/PID/status (VmRSS, VmHWM) in MB, 0 when unknown.</summary>
    private static double StatusMb(int pid, string key) => Machine.StatusBytes($"/proc/{pid}/status", key) / (1024.0 * 1024);
}
#endif
