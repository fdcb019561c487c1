using System.Diagnostics;

namespace Machina.Benchmarks;

/// <summary>
/// The whole-process benchmarks (<c>--process</c>): each scenario starts fresh processes and times them from outside, as a
/// user meets Machina; prints a results table (cold process times, cold and warm work, peak resident memory, target and
/// ratio) and, for compiling, a scaling table with the growth exponent of time and memory over 10^4 … 10^7 lines.
/// </summary>
internal static class ProcessSuite
{
    /// <summary>Every whole-process scenario, in the order they run.</summary>
    public static IReadOnlyList<ProcessScenario> All()
    {
        RobotType[] languages = [RobotType.ABB, RobotType.UR, RobotType.KUKA, RobotType.ZMORPH, RobotType.MARLIN, RobotType.HUMAN, RobotType.MACHINA];
        var all = new List<ProcessScenario>();
        all.AddRange(languages.Select(l => new CompileProcessScenario(l, huge: false)));
        all.AddRange(languages.Select(l => new CompileProcessScenario(l, huge: true)));
        all.AddRange(languages.Select(l => new CompileProcessScenario(l, huge: false, "tool")));
        all.AddRange(languages.Select(l => new CompileProcessScenario(l, huge: true, "tool")));
        all.Add(new CompileProcessScenario(RobotType.ABB, huge: false, "robot-folder"));
        all.Add(new CompileProcessScenario(RobotType.ABB, huge: false, "robot-memory"));
        all.Add(new StreamProcessScenario());
        all.Add(new FirstAckProcessScenario());
        return all;
    }

    /// <summary>Scenarios run only when named with --scenario: the built tools timed from outside (the native one may not be built).</summary>
    public static IReadOnlyList<ProcessScenario> Named()
    {
        RobotType[] languages = [RobotType.ABB, RobotType.UR, RobotType.KUKA, RobotType.ZMORPH, RobotType.MARLIN, RobotType.HUMAN, RobotType.MACHINA];
        var named = new List<ProcessScenario>();
        foreach (bool native in (bool[])[true, false])
        {
            named.AddRange(languages.SelectMany(l => Enum.GetValues<InputShape>().Select(shape => new ExternalToolScenario(l, native, shape))));
        }
        named.Add(new IssueTextProcessScenario());
        named.Add(new FormatFloorProcessScenario());
        return named;
    }

    /// <summary>Runs the selected scenarios; returns the results (also printed unless <paramref name="print"/> is false). Exit code 1 when one failed.</summary>
    public static (int ExitCode, List<ProcessResult> Results) Run(Options options, bool print = true)
    {
        List<ProcessScenario> selected = [.. All().Concat(options.Scenarios.Count == 0 ? [] : Named()).Where(s => options.Scenarios.Count == 0 || options.Scenarios.Any(n =>
            s.Name.Equals(n, StringComparison.OrdinalIgnoreCase) || s.Name.StartsWith(n + "-", StringComparison.OrdinalIgnoreCase)))];
        bool quick = options.Quick;
        bool scaling = options.Scaling ?? (!quick && options.Size is null);
        void Say(string line)
        {
            if (print)
            {
                Console.WriteLine(line);
            }
        }
        Say($"Machina whole-process benchmarks - {Machine.Current()}");
        Say($"Each run starts a fresh process (this program with --child) and times it from outside; load average {Machine.LoadAverage()} at start.");
        if (ChildProcess.Environment.Count > 0 || ChildProcess.Executable is not null)
        {
            Say($"Child: {ChildProcess.Executable ?? "this build"} {string.Join(' ', ChildProcess.Environment.Select(e => $"{e.Key}={e.Value}"))}");
        }
        if (quick)
        {
            Say("Quick mode: small sizes and one run check that every scenario works; ratios are to the full-size targets and indicative only.");
        }
        Say("");
        var total = Stopwatch.StartNew();
        var results = new List<ProcessResult>();
        var scalingRows = new List<ProcessResult>();
        using var inputs = new ProcessInputs();
        foreach (ProcessScenario scenario in selected)
        {
            int size = options.Size ?? (quick ? scenario.QuickSize : scenario.TargetSize);
            int runs = quick ? 1 : options.RunsGiven ? options.Runs : scenario.DefaultRuns;
            if (print && !Console.IsErrorRedirected)
            {
                Console.Error.Write($"\r  {scenario.Name} at {Report.Count(size)}...".PadRight(70));
            }
            ProcessResult result = Measure(scenario, size, runs, warm: scenario is CompileProcessScenario { Huge: false }, inputs);
            results.Add(result);
            if (scenario is CompileProcessScenario { Streaming: true } compile)
            {
                scalingRows.Add(result);
                if (scaling && size == 1_000_000)
                {
                    scalingRows.AddRange(new[] { 10_000, 100_000 }.Select(n => Measure(scenario, n, 1, warm: false, inputs)));
                }
            }
        }
        if (print && !Console.IsErrorRedirected)
        {
            Console.Error.Write("\r".PadRight(72) + "\r");
        }
        Say(Table(results));
        if (scalingRows.Count > 0)
        {
            Say("");
            Say("Scaling of the streaming compile (process time and peak resident memory; exponent = slope of log(value) over log(lines))");
            Say("");
            Say(ScalingTable(scalingRows));
        }
        Say("");
        Say($"{results.Count(r => r.Status == "met")} met, {results.Count(r => r.Status == "missed")} missed, {results.Count(r => r.Status == "error")} errors; " +
            $"total {Report.Time(total.Elapsed.TotalSeconds)}; load average {Machine.LoadAverage()} at the end.");
        return (results.Any(r => r.Status == "error") ? 1 : 0, results);
    }

    private static ProcessResult Measure(ProcessScenario scenario, int size, int runs, bool warm, ProcessInputs inputs)
    {
        try
        {
            return scenario.Measure(size, runs, warm, inputs);
        }
        catch (Exception ex) when (ex is InvalidOperationException or TimeoutException or IOException or System.ComponentModel.Win32Exception or System.Text.Json.JsonException or KeyNotFoundException)
        {
            return new ProcessResult(scenario.Name, scenario.Title, size) { TargetText = scenario.TargetText, Error = ex.Message };
        }
    }

    private static string Ratio(double? value) => value is double v ? v.ToString("0.00", System.Globalization.CultureInfo.InvariantCulture) : "-";

    /// <summary>The results table.</summary>
    public static string Table(IReadOnlyList<ProcessResult> rows)
    {
        string[] header = ["scenario", "size", "runs", "process median", "min", "max", "cpu", "start-up", "work cold", "work warm", "peak RSS", "target", "ratio", "status", "notes"];
        var lines = rows.Select(r => r.Error is not null
            ? new[] { r.Scenario, Report.Count(r.Size), "-", "-", "-", "-", "-", "-", "-", "-", "-", r.TargetText, "-", "error", r.Error }
            : [
                r.Scenario, Report.Count(r.Size), r.ProcessSeconds.Count.ToString(System.Globalization.CultureInfo.InvariantCulture),
                Report.Time(r.Median), Report.Time(r.Min), Report.Time(r.Max), Report.Time(r.CpuSeconds), Report.Time(r.StartupSeconds), Report.Time(r.ColdWorkSeconds),
                r.WarmWorkSeconds is double w ? Report.Time(w) : "-", Report.Bytes(r.PeakResidentBytes), r.TargetText,
                r.SecondRatio is null ? Ratio(r.Ratio) : $"{Ratio(r.Ratio)} / {Ratio(r.SecondRatio)}", r.Status, r.Note,
            ]).ToList();
        return Report.Table(header, lines);
    }

    /// <summary>Per language: process time and peak memory at each size, and their growth exponents.</summary>
    public static string ScalingTable(IReadOnlyList<ProcessResult> rows)
    {
        static string Language(string scenario) => scenario[(scenario.LastIndexOf('-') + 1)..];
        var ok = rows.Where(r => r.Error is null).ToList();
        var sizes = ok.Select(r => r.Size).Distinct().Order().ToList();
        var header = new List<string> { "language" };
        header.AddRange(sizes.Select(s => $"{Report.Count(s)}: time"));
        header.AddRange(sizes.Select(s => $"{Report.Count(s)}: peak RSS"));
        header.AddRange(["time exponent", "work exponent", "memory exponent"]);
        var lines = new List<string[]>();
        foreach (var group in ok.GroupBy(r => Language(r.Scenario)))
        {
            var bySize = group.GroupBy(r => r.Size).ToDictionary(g => g.Key, g => g.First());
            var line = new List<string> { group.Key };
            line.AddRange(sizes.Select(s => bySize.TryGetValue(s, out var r) ? Report.Time(r.Median) : "-"));
            line.AddRange(sizes.Select(s => bySize.TryGetValue(s, out var r) ? Report.Bytes(r.PeakResidentBytes) : "-"));
            line.Add(Exponent(bySize.Values.Select(r => (r.Size, r.Median))));
            line.Add(Exponent(bySize.Values.Select(r => (r.Size, r.ColdWorkSeconds))));
            line.Add(Exponent(bySize.Values.Select(r => (r.Size, (double)r.PeakResidentBytes))));
            lines.Add([.. line]);
        }
        return Report.Table([.. header], lines);
    }

    /// <summary>Least-squares slope of log(value) against log(size): 1 is linear, 0 is constant; "-" with fewer than two sizes.</summary>
    public static string Exponent(IEnumerable<(int Size, double Value)> points)
    {
        var p = points.Where(x => x.Value > 0).Select(x => (X: Math.Log(x.Size), Y: Math.Log(x.Value))).ToList();
        if (p.Select(x => x.X).Distinct().Count() < 2)
        {
            return "-";
        }
        double mx = p.Average(x => x.X), my = p.Average(x => x.Y);
        double slope = p.Sum(x => (x.X - mx) * (x.Y - my)) / p.Sum(x => (x.X - mx) * (x.X - mx));
        return slope.ToString("0.00", System.Globalization.CultureInfo.InvariantCulture);
    }
}
