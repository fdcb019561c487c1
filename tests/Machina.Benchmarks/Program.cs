// Machina's benchmark harness: times each scenario (warm-up, then the median of several runs), counts allocations, and
// compares with the targets of the performance issue. See docs/performance.md and Options.Usage.
using System.Diagnostics;
using Machina.Benchmarks;

if (args.Length > 0 && args[0] == "--fuzz")
{
    // The interpreters' fuzz run (see Fuzz/FuzzCommand.cs and docs/reliability.md).
    return Machina.Benchmarks.Fuzz.FuzzCommand.Execute(args[1..]);
}

if (args.Length > 0 && args[0] == "--child")
{
    // The process under test of the whole-process scenarios (see Process/Child.cs).
    return Child.Run(args[1..], Stopwatch.GetTimestamp());
}

Options options;
try
{
    options = Options.Parse(args);
}
catch (ArgumentException ex)
{
    Console.Error.WriteLine(ex.Message);
    Console.Error.WriteLine(Options.Usage);
    return 2;
}
if (options.Help)
{
    Console.WriteLine(Options.Usage);
    return 0;
}

if (options.Differential)
{
    return options.Program is int program
        ? Machina.Benchmarks.Differential.DifferentialSuite.Show(program, options.Brands, Console.Out)
        : Machina.Benchmarks.Differential.DifferentialSuite.Run(options.Size ?? 2000, options.Seed, options.Brands, Console.Out);
}
#if MACHINA_ONLINE
if (options.Restarts is int restartTrials)
{
    return RestartRun.Run(restartTrials, options.Resend, options.Brands);
}
if (options.RtdeRate)
{
    foreach ((string key, string value) in options.ChildEnvironment)
    {
        ChildProcess.Environment[key] = value;
    }
    return options.Process ? RtdeRateApartRun.Run(options.Size, options.NativeTool) : RtdeRateRun.Run(options.Size);
}
if (options.Twins is int twins)
{
    ExternalToolScenario.NativePath = options.NativeTool;
    return TwinsSideBySideRun.Run(twins, options.Size, options.Brands);
}
#endif

if (options.Process)
{
    foreach ((string key, string value) in options.ChildEnvironment)
    {
        ChildProcess.Environment[key] = value;
    }
    ChildProcess.Executable = options.ChildExecutable;
    ExternalToolScenario.NativePath = options.NativeTool;
    if (options.List)
    {
        foreach (ProcessScenario s in ProcessSuite.All().Concat(ProcessSuite.Named()))
        {
            Console.WriteLine($"{s.Name,-28} {s.Title} (target: {s.TargetText})");
        }
        return 0;
    }
    return ProcessSuite.Run(options).ExitCode;
}

var workloads = new Workloads();
IReadOnlyList<Scenario> all = Catalog.All(workloads);
if (options.List)
{
    foreach (Scenario s in all)
    {
        Console.WriteLine($"{s.Name,-16} {s.Title} (target: {s.Target?.Text ?? "none"})");
    }
    return 0;
}
List<Scenario> selected = all.Where(options.Selects).ToList();
if (selected.Count == 0)
{
    Console.Error.WriteLine($"No scenario matches {string.Join(", ", options.Scenarios)}; --list shows them.");
    return 2;
}

Machine machine = Machine.Current();
bool quick = options.Quick;
int runs = quick ? 1 : options.Runs;
int warmups = quick ? Math.Min(options.Warmups, 1) : options.Warmups;
bool scaling = options.Scaling ?? (!quick && options.Size is null);
bool interactive = !Console.IsErrorRedirected;
var runner = new Runner(warmups, runs, message =>
{
    if (interactive)
    {
        Console.Error.Write($"\r  {message}".PadRight(70));
    }
}, settle: !quick);

if (options.Json)
{
    Console.WriteLine(System.Text.Json.JsonSerializer.Serialize(new
    {
        table = "machine", cpu = machine.Cpu, cores = machine.Cores, runtime = machine.Runtime, os = machine.Os, commit = machine.Commit,
        serverGc = machine.ServerGc, configuration = machine.Configuration, runs, warmups, loadAverage = Machine.LoadAverage(),
    }, Report.JsonOptions));
}
else
{
    Console.WriteLine($"Machina benchmarks - {machine}");
    Console.WriteLine($"Median of {runs} run(s) after at least {warmups} warm-up(s) (more until the JIT settles); load average {Machine.LoadAverage()} at start.");
    Console.WriteLine("ratio = median time per unit / target time per unit (<= 1.00 meets it); cpu = processor time of all threads during the run, the JIT's included;");
    Console.WriteLine("jit cpu = the JIT's tiered-compilation thread during the run ((busy): still compiling in a measured run, after running such runs again); -jit = cpu/unit without it.");
    if (quick)
    {
        Console.WriteLine("Quick mode: one run of 10^4 units checks that every scenario works; its timings are indicative only.");
    }
    Console.WriteLine();
}

var total = Stopwatch.StartNew();
var results = new List<Measurement>();
var scalingRows = new List<Measurement>();
foreach (Scenario scenario in selected)
{
    int size = options.Size ?? (quick ? Math.Min(scenario.TargetSize, 10_000) : scenario.TargetSize);
    Measurement main = runner.Run(scenario, size);
    results.Add(main);
    Emit(main, "results");
    if (!scaling || main.Runs == 0)
    {
        continue;
    }
    foreach (int n in scenario.ScalingSizes)
    {
        Measurement m = n == main.Size ? main : runner.Run(scenario, n);
        scalingRows.Add(m);
        if (n != main.Size)
        {
            Emit(m, "scaling");
        }
    }
}
if (interactive)
{
    Console.Error.Write("\r".PadRight(72) + "\r");
}

if (!options.Json)
{
    Console.WriteLine("Results");
    Console.WriteLine();
    Console.WriteLine(Report.Results(results));
    if (scalingRows.Count > 0)
    {
        Console.WriteLine();
        Console.WriteLine("Scaling (time and allocations per unit; growth = per-unit time at the largest size over the smallest, 1.00x is linear)");
        Console.WriteLine();
        Console.WriteLine(Report.Scaling(scalingRows));
    }
    Console.WriteLine();
    int met = results.Count(r => r.Status == "met");
    int missed = results.Count(r => r.Status == "missed");
    int unavailable = results.Count(r => r.Status == "not available");
    int errors = results.Count(r => r.Status == "error");
    Console.WriteLine($"{met} met, {missed} missed, {unavailable} not available, {errors} errors; total {Report.Time(total.Elapsed.TotalSeconds)}; load average {Machine.LoadAverage()} at the end.");
}
return results.Any(r => r.Status == "error") ? 1 : 0;

void Emit(Measurement m, string table)
{
    if (options.Json)
    {
        Console.WriteLine(Report.Json(m, table));
    }
}
