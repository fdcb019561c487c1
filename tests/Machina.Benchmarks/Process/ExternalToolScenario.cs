using System.Diagnostics;
using System.Globalization;

namespace Machina.Benchmarks;

/// <summary>
/// A built <c>machina</c> run as users run it, timed from outside: <c>machina compile FILE --brand B --out DIR</c> on the 10^6-line
/// file, under <c>/usr/bin/time</c> for its processor time (user + system) and peak resident memory. <c>cold-native-&lt;brand&gt;</c>
/// runs the native file (PublishAot; <c>--native PATH</c>, default src/Machina.Cli/bin/native/linux-x64/machina);
/// <c>cold-jit-&lt;brand&gt;</c> runs the JIT tool (its apphost and runtime settings, built beside this program) the same way.
/// Only run when named (<c>--scenario cold-native</c>): the quick smoke test has no native file. Each brand also has one
/// scenario per other <see cref="InputShape"/> (<c>cold-native-abb-small</c>, …), the same target for each.
/// </summary>
internal sealed class ExternalToolScenario(RobotType brand, bool native, InputShape shape = InputShape.Mixed) : ProcessScenario
{
    private const double Mb = 1 << 20;

    /// <summary>The native tool, from --native (null: the default place in the repository).</summary>
    public static string? NativePath { get; set; }

    public override string Name => $"{(native ? "cold-native" : "cold-jit")}-{brand.ToString().ToLowerInvariant()}{InputShapes.Suffix(shape)}";

    public override string Title => $"Fresh process: the {(native ? "native" : "JIT")} machina compiles a {Report.Count(TargetSize)}-line {shape.ToString().ToLowerInvariant()} file to {brand} files (timed from outside)";

    public override int TargetSize => 1_000_000;

    public override int QuickSize => 10_000;

    public override int DefaultRuns => 5;

    public override string TargetText => native ? "<= 0.5 s cpu, <= 40 MB resident" : "<= 1 s cpu";

    public override ProcessResult Measure(int size, int runs, bool warm, ProcessInputs inputs)
    {
        string file = inputs.InstructionFile(size, shape);
        string folder = inputs.Folder(Name);
        string tool = native ? Native() : Jit();
        var walls = new List<double>();
        var cpus = new List<double>();
        long peak = 0;
        for (int i = 0; i < runs; i++)
        {
            Settle(folder);
            (double wall, double cpu, long resident) = RunTimed(tool, ["compile", file, "--brand", brand.ToString(), "--out", folder, "--name", "Bench"], Timeout(size));
            walls.Add(wall);
            cpus.Add(cpu);
            peak = Math.Max(peak, resident);
        }
        double medianCpu = ProcessResult.Percentile(cpus, 0.5);
        return new ProcessResult(Name, Title, size)
        {
            ProcessSeconds = walls,
            CpuSeconds = medianCpu,
            PeakResidentBytes = peak,
            TargetText = size == TargetSize ? TargetText : $"{TargetText} (at {Report.Count(TargetSize)})",
            Ratio = medianCpu / (native ? 0.5 : 1.0),
            SecondRatio = native ? peak / (40 * Mb) : null,
            Note = $"cpu per run {string.Join(" / ", cpus.Select(c => c.ToString("0.00", CultureInfo.InvariantCulture)))} s",
        };
    }

    /// <summary>The native machina to run: --native, or where the linux-x64 publish puts it.</summary>
    internal static string Native()
    {
        string path = NativePath ?? Path.Combine(RepositoryRoot(), "src/Machina.Cli/bin/native/linux-x64/machina");
        return File.Exists(path) ? path
            : throw new FileNotFoundException($"The native machina is not built ({path}): dotnet publish src/Machina.Cli -p:PublishProfile=linux-x64, or give --native PATH.");
    }

    private static string Jit()
    {
        string path = Path.Combine(Path.GetDirectoryName(typeof(ExternalToolScenario).Assembly.Location)!, "Machina.Cli");
        return File.Exists(path) ? path : throw new FileNotFoundException($"The JIT machina apphost is not beside the benchmarks ({path}).");
    }

    private static string RepositoryRoot()
    {
        string? folder = AppContext.BaseDirectory;
        while (folder is not null && !File.Exists(Path.Combine(folder, "Machina.sln")))
        {
            folder = Path.GetDirectoryName(folder);
        }
        return folder ?? throw new InvalidOperationException("Machina.sln not found above the benchmarks.");
    }

    /// <summary>
    /// Before a run, outside its time: removes the last run's output and waits until the disk has taken what is written
    /// (<c>sync</c>). Otherwise each run also paid for dropping the last run's file (the URScript file is 313 MB) while the
    /// kernel was still writing it out, which a compile into an empty folder, or over an old file long on the disk, does not.
    /// </summary>
    private static void Settle(string folder)
    {
        if (Directory.Exists(folder))
        {
            Directory.Delete(folder, recursive: true);
        }
        using Process? sync = Process.Start(new ProcessStartInfo("sync") { UseShellExecute = false });
        sync?.WaitForExit();
    }

    /// <summary>Runs <paramref name="tool"/> under /usr/bin/time; its wall time from outside, processor time and peak resident memory.</summary>
    internal static (double Wall, double Cpu, long PeakResident) RunTimed(string tool, IEnumerable<string> arguments, TimeSpan timeout)
    {
        string report = Path.GetTempFileName();
        try
        {
            var start = new ProcessStartInfo("/usr/bin/time") { RedirectStandardOutput = true, RedirectStandardError = true, UseShellExecute = false };
            foreach (string a in (string[])["-f", "%U %S %M", "-o", report, tool, .. arguments])
            {
                start.ArgumentList.Add(a);
            }
            long started = Stopwatch.GetTimestamp();
            using Process process = Process.Start(start) ?? throw new InvalidOperationException("/usr/bin/time did not start.");
            Task<string> output = process.StandardOutput.ReadToEndAsync();
            Task<string> error = process.StandardError.ReadToEndAsync();
            if (!process.WaitForExit(timeout))
            {
                process.Kill(entireProcessTree: true);
                throw new TimeoutException($"{tool} did not finish within {timeout.TotalSeconds:0} s.");
            }
            double wall = Stopwatch.GetElapsedTime(started).TotalSeconds;
            process.WaitForExit();
            if (process.ExitCode != 0)
            {
                throw new InvalidOperationException($"{tool} failed with exit code {process.ExitCode}: {error.Result.Trim()} {output.Result.Trim()}");
            }
            string[] parts = File.ReadAllText(report).Trim().Split('\n')[^1].Split(' ');
            double cpu = double.Parse(parts[0], CultureInfo.InvariantCulture) + double.Parse(parts[1], CultureInfo.InvariantCulture);
            return (wall, cpu, long.Parse(parts[2], CultureInfo.InvariantCulture) * 1024);
        }
        finally
        {
            File.Delete(report);
        }
    }
}

/// <summary>
/// A fresh process issues 4·10^5 relative moves on an ABB robot, compiles them in memory and takes each file's text (the child
/// kind <c>issue-text</c>): a script user's whole program, start-up included. Issue 45 asks it at least
/// <see cref="Speedup"/> times as fast as the original library's recorded <see cref="OriginalSeconds"/>: at most 0.344 s. The
/// row's ratio is the median over that target; the note gives the speed-up over the original and each phase of the work
/// (issue, compile, text: wall time, processor time, minor page faults and bytes allocated, medians over the runs).
/// </summary>
internal sealed class IssueTextProcessScenario : ProcessScenario
{
    /// <summary>The original library's recorded time for this job (issue 45), seconds.</summary>
    internal const double OriginalSeconds = 27.5;

    /// <summary>How many times faster than the original issue 45 asks the job to be.</summary>
    internal const double Speedup = 80;

    /// <summary>The target: the original's time over the speed-up asked, 0.34375 s.</summary>
    internal const double TargetSeconds = OriginalSeconds / Speedup;

    public override string Name => "cold-issue-text";

    public override string Title => $"Fresh process: issue {Report.Count(TargetSize)} moves, compile to RAPID in memory, take the text";

    public override int TargetSize => 400_000;

    public override int QuickSize => 10_000;

    public override int DefaultRuns => 5;

    public override string TargetText => $"<= {TargetSeconds.ToString("0.000", CultureInfo.InvariantCulture)} s ({Speedup:0}x the original's {OriginalSeconds.ToString("0.0", CultureInfo.InvariantCulture)} s)";

    public override ProcessResult Measure(int size, int runs, bool warm, ProcessInputs inputs)
    {
        string[] arguments = ["issue-text", $"moves={size}"];
        var children = Enumerable.Range(0, runs).Select(_ => ChildProcess.Run(arguments, Timeout(size))).ToList();
        ProcessResult result = CompileProcessScenario.Summarize(this, size, children);
        string phases = string.Join(", ", ((string[])["issue", "compile", "text"]).Select(name => Phase(children, name)));
        return result with
        {
            TargetText = size == TargetSize ? TargetText : $"{TargetText} (at {Report.Count(TargetSize)})",
            Ratio = result.Median / TargetSeconds,
            Note = $"{(OriginalSeconds / result.Median).ToString("0.0", CultureInfo.InvariantCulture)}x the original; {phases}; "
                + $"{children[0].Report.GetProperty("extra").GetProperty("characters").GetInt64()} characters",
        };
    }

    /// <summary>One phase of the work, medians over the runs: "compile 180 ms (cpu 175 ms, 19,624 faults, 85.8 MB allocated)".</summary>
    private static string Phase(List<ChildRun> children, string name)
    {
        double Median(int i) => ProcessResult.Percentile(
            [.. children.Select(c => c.Report.GetProperty("extra").GetProperty("phases").GetProperty(name)[i].GetDouble())], 0.5);
        return $"{name} {Report.Time(Median(0))} (cpu {Report.Time(Median(1))}, {Report.Count(Median(2))} faults, "
            + $"{(Median(3) / 1e6).ToString("0.0", CultureInfo.InvariantCulture)} MB allocated)";
    }
}

/// <summary>
/// The yardstick: a fresh process formats the numbers of the 10^6-line file (three per move, as the compilers write them)
/// with .NET's shortest round-trip formatting into a buffer, nothing else (child kind <c>format-floor</c>).
/// </summary>
internal sealed class FormatFloorProcessScenario : ProcessScenario
{
    public override string Name => "cold-format-floor";

    public override string Title => $"Fresh process: shortest round-trip text of the numbers of {Report.Count(TargetSize)} moves alone (the floor)";

    public override int TargetSize => 1_000_000;

    public override int QuickSize => 10_000;

    public override int DefaultRuns => 5;

    public override string TargetText => "(yardstick)";

    public override ProcessResult Measure(int size, int runs, bool warm, ProcessInputs inputs)
    {
        var children = Enumerable.Range(0, runs).Select(_ => ChildProcess.Run(["format-floor", $"moves={size}"], Timeout(size))).ToList();
        ProcessResult result = CompileProcessScenario.Summarize(this, size, children);
        return result with
        {
            TargetText = TargetText,
            Note = $"{children[0].Report.GetProperty("extra").GetProperty("characters").GetInt64()} characters; the formatting alone "
                + string.Join(" / ", children.Select(c => c.Report.GetProperty("extra").GetProperty("formatSeconds").GetDouble().ToString("0.000", System.Globalization.CultureInfo.InvariantCulture))) + " s",
        };
    }
}
