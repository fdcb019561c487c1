using System.Diagnostics;
using System.Text.Json;

namespace Machina.Benchmarks;

/// <summary>One finished child process: its wall time measured from outside, and what it reported about itself.</summary>
internal sealed record ChildRun(long StartTimestamp, long ExitTimestamp, JsonElement Report)
{
    private static double Seconds(long ticks) => ticks / (double)Stopwatch.Frequency;

    /// <summary>From just before the process was started until it had exited.</summary>
    public double ProcessSeconds => Seconds(ExitTimestamp - StartTimestamp);

    /// <summary>From process start to the first line of Main (runtime start-up, assembly loading).</summary>
    public double StartupSeconds => Seconds(Timestamp("main") - StartTimestamp);

    /// <summary>Duration of each repetition of the work inside the child; the first is the cold one.</summary>
    public double[] Iterations => [.. Report.GetProperty("iterations").EnumerateArray().Select(e => e.GetDouble())];

    /// <summary>Processor time of the child, all threads, up to its report.</summary>
    public double CpuSeconds => Report.GetProperty("cpuSeconds").GetDouble();

    /// <summary>Peak resident memory of the child (VmHWM).</summary>
    public long PeakResidentBytes => Report.GetProperty("peakResidentBytes").GetInt64();

    /// <summary>A Stopwatch timestamp the child reported (top level or under "extra").</summary>
    public long Timestamp(string name) =>
        Report.TryGetProperty(name, out JsonElement e) ? e.GetInt64() : Report.GetProperty("extra").GetProperty(name).GetInt64();

    /// <summary>Seconds between a start timestamp (of either process) and the child's timestamp <paramref name="name"/>.</summary>
    public double SecondsBetween(long from, string name) => Seconds(Timestamp(name) - from);
}

/// <summary>Starts this benchmark program again as a child (<c>--child …</c>) and times it from outside.</summary>
internal static class ChildProcess
{
    /// <summary>Environment variables set for every child (e.g. DOTNET_TieredPGO=0), from --child-env.</summary>
    public static Dictionary<string, string> Environment { get; } = [];

    /// <summary>Another build of this program to run as the child (e.g. a ReadyToRun publish), from --child-exe; null for this one.</summary>
    public static string? Executable { get; set; }

    /// <summary>The runtime settings the <c>machina</c> tool ships with (its runtimeconfig.json, built beside this program).</summary>
    public static string ToolRuntimeConfig => Path.Combine(Path.GetDirectoryName(Executable ?? typeof(ChildProcess).Assembly.Location)!, "Machina.Cli.runtimeconfig.json");

    /// <summary>
    /// Runs a child to its end (bounded by <paramref name="timeout"/>) and returns its report; throws with its error output when it
    /// fails. With <paramref name="runtimeConfig"/>, the child runs under those runtime settings (<c>dotnet exec --runtimeconfig</c>).
    /// </summary>
    public static ChildRun Run(IEnumerable<string> arguments, TimeSpan timeout, string? runtimeConfig = null)
    {
        string self = Executable is null ? typeof(ChildProcess).Assembly.Location : Path.ChangeExtension(Executable, ".dll");
        string appHost = Path.ChangeExtension(self, null);
        var start = new ProcessStartInfo
        {
            RedirectStandardOutput = true,
            RedirectStandardError = true,
            UseShellExecute = false,
        };
        if (runtimeConfig is not null)
        {
            start.FileName = "dotnet";
            start.ArgumentList.Add("exec");
            start.ArgumentList.Add("--runtimeconfig");
            start.ArgumentList.Add(runtimeConfig);
            start.ArgumentList.Add(self);
        }
        else if (Executable is not null)
        {
            start.FileName = Executable;
        }
        else if (File.Exists(appHost))
        {
            start.FileName = appHost;
        }
        else
        {
            start.FileName = "dotnet";
            start.ArgumentList.Add(self);
        }
        start.ArgumentList.Add("--child");
        foreach (string argument in arguments)
        {
            start.ArgumentList.Add(argument);
        }
        foreach ((string key, string value) in Environment)
        {
            start.Environment[key] = value;
        }
        long started = Stopwatch.GetTimestamp();
        using Process process = Process.Start(start) ?? throw new InvalidOperationException("The child process did not start.");
        Task<string> output = process.StandardOutput.ReadToEndAsync();
        Task<string> error = process.StandardError.ReadToEndAsync();
        if (!process.WaitForExit(timeout))
        {
            process.Kill(entireProcessTree: true);
            throw new TimeoutException($"The child process ({string.Join(' ', start.ArgumentList)}) did not finish within {timeout.TotalSeconds:0} s.");
        }
        long exited = Stopwatch.GetTimestamp();
        process.WaitForExit();
        string text = output.Result;
        if (process.ExitCode != 0)
        {
            throw new InvalidOperationException($"The child process failed with exit code {process.ExitCode}: {error.Result.Trim()} {text.Trim()}");
        }
        string last = text.Split('\n', StringSplitOptions.RemoveEmptyEntries | StringSplitOptions.TrimEntries).LastOrDefault()
            ?? throw new InvalidOperationException("The child process reported nothing.");
        return new ChildRun(started, exited, JsonDocument.Parse(last).RootElement.Clone());
    }
}
