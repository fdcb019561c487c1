using System.Diagnostics;
using Machina.Simulation;

namespace Machina.Benchmarks;

/// <summary>A whole-process scenario: starts the process under test (this program with <c>--child</c>) and times it from outside.</summary>
internal abstract class ProcessScenario
{
    public abstract string Name { get; }

    public abstract string Title { get; }

    /// <summary>The size the target is stated for, and the size used by --quick.</summary>
    public abstract int TargetSize { get; }

    public abstract int QuickSize { get; }

    /// <summary>Runs when --runs is not given (few for the long ones).</summary>
    public virtual int DefaultRuns => 3;

    public abstract string TargetText { get; }

    /// <summary>Measures <paramref name="runs"/> fresh processes at <paramref name="size"/>; with <paramref name="warm"/> also one child repeating the work.</summary>
    public abstract ProcessResult Measure(int size, int runs, bool warm, ProcessInputs inputs);

    protected static TimeSpan Timeout(int size) => TimeSpan.FromMinutes(2) + TimeSpan.FromMilliseconds(size / 100.0);
}

/// <summary>
/// (a)/(b): a fresh process reads an instruction file and compiles it into a folder, through one of three paths (see
/// <c>Child.Compile</c>): the streaming entry point, or a robot holding the whole program, compiled to a folder or in memory.
/// </summary>
internal sealed class CompileProcessScenario(RobotType brand, bool huge, string path = "stream") : ProcessScenario
{
    private const double Mb = 1 << 20;

    public override string Name => path == "tool"
        ? $"{(huge ? "cold-tool-10m" : "cold-tool")}-{brand.ToString().ToLowerInvariant()}"
        : $"{(huge ? "cold-compile-10m" : "cold-compile")}{(path == "stream" ? "" : "-" + path)}-{brand.ToString().ToLowerInvariant()}";

    public override string Title => path == "tool"
        ? $"Fresh process: machina compile of a {Report.Count(TargetSize)}-line instruction file to {brand} files (the tool's runtime settings)"
        : $"Fresh process: {Report.Count(TargetSize)}-line instruction file to {brand} files ({path})";

    public override int TargetSize => huge ? 10_000_000 : 1_000_000;

    public override int QuickSize => huge ? 20_000 : 10_000;

    public override int DefaultRuns => huge ? 1 : 3;

    private double TargetSeconds => huge ? 12 : 1.5;

    public override string TargetText => huge ? "<= 12 s, <= 150 MB resident" : "<= 1.5 s, <= 150 MB resident";

    /// <summary>The language compiled.</summary>
    public RobotType Brand => brand;

    /// <summary>True for the 10^7-line scenarios (no warm repetition: one process is long enough).</summary>
    public bool Huge => huge;

    /// <summary>True for the streaming entry point (the robot paths are what it replaces; the tool is a user of it).</summary>
    public bool Streaming => path == "stream";

    /// <summary>True for the <c>machina compile</c> command run with the tool's runtime settings.</summary>
    public bool Tool => path == "tool";

    public override ProcessResult Measure(int size, int runs, bool warm, ProcessInputs inputs)
    {
        string file = inputs.InstructionFile(size);
        string folder = inputs.Folder(Name);
        string[] arguments = ["compile", $"file={file}", $"brand={brand}", $"folder={folder}", $"path={path}"];
        string? runtimeConfig = path == "tool" ? ChildProcess.ToolRuntimeConfig : null;
        var children = Enumerable.Range(0, runs).Select(_ => ChildProcess.Run(arguments, Timeout(size), runtimeConfig)).ToList();
        if (path == "tool" && children.Any(c => c.Report.GetProperty("extra").GetProperty("tieredCompilation").ValueKind != System.Text.Json.JsonValueKind.False))
        {
            throw new InvalidOperationException($"The child did not run with the tool's runtime settings ({runtimeConfig}).");
        }
        double? warmSeconds = null;
        if (warm)
        {
            ChildRun repeated = ChildProcess.Run([.. arguments, $"repeat={(runs == 1 ? 2 : 3)}"], Timeout(size * 3), runtimeConfig);
            warmSeconds = repeated.Iterations.Skip(1).Min();
        }
        var result = Summarize(this, size, children) with { WarmWorkSeconds = warmSeconds };
        // The targets are stated for the target size; at other sizes the ratio is to the same target (informative).
        return result with
        {
            TargetText = size == TargetSize ? TargetText : $"{TargetText} (at {Report.Count(TargetSize)})",
            Ratio = result.Median / TargetSeconds,
            SecondRatio = result.PeakResidentBytes / (150 * Mb),
            Note = $"{Report.Time(result.ColdWorkSeconds)} compile cold in-process",
        };
    }

    internal static ProcessResult Summarize(ProcessScenario scenario, int size, List<ChildRun> children) => new(scenario.Name, scenario.Title, size)
    {
        ProcessSeconds = [.. children.Select(c => c.ProcessSeconds)],
        StartupSeconds = ProcessResult.Percentile([.. children.Select(c => c.StartupSeconds)], 0.5),
        ColdWorkSeconds = ProcessResult.Percentile([.. children.Select(c => c.Iterations[0])], 0.5),
        PeakResidentBytes = children.Max(c => c.PeakResidentBytes),
        CpuSeconds = ProcessResult.Percentile([.. children.Select(c => c.CpuSeconds)], 0.5),
    };
}

/// <summary>(c): a fresh process connects to the virtual ABB controller (run by this program) and streams HelloRobot-style moves.</summary>
internal sealed class StreamProcessScenario : ProcessScenario
{
    public override string Name => "cold-stream";

    public override string Title => "Fresh process: connect to the virtual ABB controller and stream moves (default window)";

    public override int TargetSize => 10_000;

    public override int QuickSize => 1_000;

    public override string TargetText => ">= 20,000 actions/s acknowledged";

    public override ProcessResult Measure(int size, int runs, bool warm, ProcessInputs inputs)
    {
        var children = new List<ChildRun>();
        var rates = new List<double>();
        for (int i = 0; i < runs; i++)
        {
            // The RAPID twin runs the driver modules; an IRB 1600 reaches every point the child streams to.
            var controller = new VirtualAbbController(new VirtualAbbControllerOptions { InstantExecution = true, Model = RobotModels.Get("IRB 1600-8/1.45") });
            try
            {
                controller.StartAsync().GetAwaiter().GetResult();
                ChildRun child = ChildProcess.Run(["stream", $"port={controller.Port}", $"count={size}"], Timeout(size * 50));
                children.Add(child);
                rates.Add(size / child.SecondsBetween(child.Timestamp("firstIssueTimestamp"), "doneTimestamp"));
                if (controller.AcknowledgementsSent < size)
                {
                    throw new InvalidOperationException($"The controller acknowledged {controller.AcknowledgementsSent} of {size} actions.");
                }
            }
            finally
            {
                controller.DisposeAsync().AsTask().GetAwaiter().GetResult();
            }
        }
        ProcessResult result = CompileProcessScenario.Summarize(this, size, children);
        double rate = ProcessResult.Percentile(rates, 0.5);
        double connect = ProcessResult.Percentile([.. children.Select(c => (c.Timestamp("firstIssueTimestamp") - c.StartTimestamp) / (double)Stopwatch.Frequency)], 0.5);
        return result with
        {
            TargetText = TargetText,
            Ratio = 20_000 / rate,
            Note = $"{Report.Count(rate)} actions/s from first issue to last acknowledgement; connected {Report.Time(connect)} after process start",
        };
    }
}

/// <summary>
/// (d): a fresh process connects to a fake ABB controller (run by this program, see <see cref="FakeAbbController"/>) with a
/// window of one action, so each acknowledgement releases the next action: the time from process start to the first
/// acknowledgement, and the latency from each acknowledgement to the arrival of the next request (p50, p99, max).
/// </summary>
internal sealed class FirstAckProcessScenario : ProcessScenario
{
    public override string Name => "cold-first-ack";

    public override string Title => "Fresh process: start-up to first acknowledgement, then acknowledgement-to-next-release latency (window 1)";

    public override int TargetSize => 100_000;

    public override int QuickSize => 1_000;

    public override int DefaultRuns => 1;

    public override string TargetText => "<= 300 ms to first ack, p99 ack-to-release <= 1 ms";

    public override ProcessResult Measure(int size, int runs, bool warm, ProcessInputs inputs)
    {
        var children = new List<ChildRun>();
        var firstAcks = new List<double>();
        var latencies = new List<double>();
        for (int i = 0; i < runs; i++)
        {
            using var controller = new FakeAbbController(size);
            ChildRun child = ChildProcess.Run(["stream", $"port={controller.Port}", $"count={size}", "window=1"], Timeout(size * 50));
            controller.Wait(TimeSpan.FromSeconds(10));
            if (controller.Error is not null || controller.Acknowledged < size)
            {
                throw new InvalidOperationException($"The fake controller acknowledged {controller.Acknowledged} of {size} actions. {controller.Error}");
            }
            children.Add(child);
            firstAcks.Add((controller.AckTimestamps[0] - child.StartTimestamp) / (double)Stopwatch.Frequency);
            latencies.AddRange(controller.ReleaseLatencies());
        }
        ProcessResult result = CompileProcessScenario.Summarize(this, size, children);
        double first = ProcessResult.Percentile(firstAcks, 0.5);
        double p50 = ProcessResult.Percentile(latencies, 0.5), p99 = ProcessResult.Percentile(latencies, 0.99), max = latencies.Count > 0 ? latencies.Max() : double.NaN;
        return result with
        {
            TargetText = TargetText,
            Ratio = first / 0.3,
            SecondRatio = p99 / 0.001,
            Note = $"first ack {Report.Time(first)} after start; ack-to-release p50 {Report.Time(p50)}, p99 {Report.Time(p99)}, max {Report.Time(max)} over {Report.Count(latencies.Count)}",
        };
    }
}

/// <summary>Instruction files of each size (written once, streamed to disk) and output folders, in a temporary folder removed at the end.</summary>
internal sealed class ProcessInputs : IDisposable
{
    private readonly string _root = Path.Combine(Path.GetTempPath(), $"machina-process-bench-{Environment.ProcessId}");

    /// <summary>An instruction file of <paramref name="lines"/> lines: an absolute start, then lines of <paramref name="shape"/> (by default the mix of the in-process parse scenario).</summary>
    public string InstructionFile(int lines, InputShape shape = InputShape.Mixed)
    {
        string path = Path.Combine(_root, $"input-{lines}{InputShapes.Suffix(shape)}.machina");
        if (!File.Exists(path))
        {
            Directory.CreateDirectory(_root);
            using (var writer = new StreamWriter(path + ".tmp", false, new System.Text.UTF8Encoding(false), 1 << 16))
            {
                var random = new Random(6);
                writer.Write("MoveTo(300, 0, 500);\n");
                for (int i = 1; i < lines; i++)
                {
                    writer.Write(InputShapes.Line(shape, i, random));
                    writer.Write('\n');
                }
            }
            File.Move(path + ".tmp", path);
        }
        return path;
    }

    /// <summary>An output folder for a scenario.</summary>
    public string Folder(string name) => Path.Combine(_root, "out-" + name);

    public void Dispose()
    {
        if (Directory.Exists(_root))
        {
            Directory.Delete(_root, recursive: true);
        }
    }
}
