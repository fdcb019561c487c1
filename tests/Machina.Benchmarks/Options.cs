using System.Globalization;

namespace Machina.Benchmarks;

/// <summary>Command-line options of the benchmark harness.</summary>
internal sealed record Options
{
    public const string Usage = """
        Usage: dotnet run -c Release --project tests/Machina.Benchmarks -- [options]
          --scenario NAME   run only scenarios named NAME or starting with NAME- (repeatable, or comma-separated):
                            issue, compile (compile-abb, compile-ur, ...), folder (folder-abb, ...), parse, cli-compile, stream, ik
          --size N          run at N units instead of each scenario's target size (no scaling table)
          --scaling         add the scaling table (10^4, 10^5, 10^6) even with --size or --quick
          --no-scaling      skip the scaling table
          --runs N          measured runs per scenario (median is reported; default 3)
          --warmup N        warm-up runs before measuring (default 1); more follow, up to 15 and 20 s, until one in which the
                            JIT's tiered-compilation thread used at most 2 % of the processor time (not with --quick;
                            --warmup 0: none at all)
          --quick           small sizes (10^4) and 1 run, to check that everything works
          --process         the whole-process scenarios instead: fresh processes timed from outside (cold-compile-abb,
                            cold-compile-10m-…, cold-stream, cold-first-ack); see docs/performance.md
          --child-env K=V   (with --process) set an environment variable in every child, e.g. DOTNET_TieredPGO=0 (repeatable)
          --child-exe PATH  (with --process) run another build of this program as the child, e.g. a ReadyToRun publish
          --native PATH     (with --process) the native machina the cold-native-… scenarios run (default: where
                            dotnet publish src/Machina.Cli -p:PublishProfile=linux-x64 puts it)
          --differential    the differential property instead of timings (issue 46): each program compiled and run on the
                            brand's twin, and streamed through Machina's driver to the same twin, must reach the same poses,
                            joints and outputs and end the same way; --size N random programs per brand (default 2000) with
                            --seed S (default 1), plus samples/programs; --brand abb|ur|kuka (repeatable; default all three);
                            --program SEED shows the program of one seed (as a DISAGREE line names it) and both runs' steps
          --fuzz ...        the interpreters' fuzz run instead (first argument; --fuzz --help for its options)
          --restarts N      the controller-restart schedule instead: N seeded trials per brand (ABB, UR, KUKA), counting
                            actions run twice and not sent again (docs/reliability.md, "Controller restarts"); --resend
                            runs it with ResendAfterControllerRestart; --brand abb|ur|kuka picks brands (default all three)
          --rtde-rate       the virtual UR's RTDE output rate instead (issue 45): a client of our own at 125 and 500 Hz, alone and
                            beside a stream of --size moves (default 10^5); asked, delivered, p50/p99 period error, load.
                            With --process: the twin in its own process (`machina sim ur`, the native one with --native PATH,
                            else the JIT tool beside the benchmarks), the stream's host in a child, the reader here;
                            --child-env K=V goes to the twin and the host
          --twins N         N native twins side by side instead (issue 45): `machina sim` processes (--native), each serving
                            its own host in this process --size moves (default 10^4); ready time, memory, each host's rate;
                            --brand abb|ur|kuka picks brands (default all three)
          --json            one JSON object per line instead of tables
          --list            list the scenarios and exit
          --help            this text
        Environment: MACHINA_BENCH_THREADS=1 prints each measured run's processor time by thread (µs and times run per unit);
        MACHINA_BENCH_ALLOCS=1 prints the types allocated during the measured runs (sampled, bytes per unit).
        MACHINA_BENCH_JIT=1 prints the methods the JIT compiled during each measured run (tier, compiling time, costliest first).
        """;

    public List<string> Scenarios { get; init; } = [];
    public int? Size { get; init; }
    public bool? Scaling { get; init; }
    public int Runs { get; init; } = 3;
    public bool RunsGiven { get; init; }
    public bool Process { get; init; }
    public bool Differential { get; init; }
    public int Seed { get; init; } = 1;
    public int? Program { get; init; }
    public List<string> Brands { get; init; } = [];
    public int? Restarts { get; init; }
    public bool Resend { get; init; }
    public bool RtdeRate { get; init; }

    /// <summary>With --twins N: N native twins side by side, each serving its own host (issue 45), instead of the scenarios.</summary>
    public int? Twins { get; init; }
    public Dictionary<string, string> ChildEnvironment { get; init; } = [];
    public string? ChildExecutable { get; init; }
    public string? NativeTool { get; init; }
    public int Warmups { get; init; } = 1;
    public bool Quick { get; init; }
    public bool Json { get; init; }
    public bool List { get; init; }
    public bool Help { get; init; }

    /// <summary>Reads the arguments; throws <see cref="ArgumentException"/> with a readable message on a bad one.</summary>
    public static Options Parse(string[] args)
    {
        var options = new Options();
        for (int i = 0; i < args.Length; i++)
        {
            string arg = args[i];
            options = arg switch
            {
                "--scenario" or "-s" => options with { Scenarios = [.. options.Scenarios, .. Value(args, ref i).Split(',', StringSplitOptions.RemoveEmptyEntries | StringSplitOptions.TrimEntries)] },
                "--size" or "-n" => options with { Size = Positive(args, ref i) },
                "--runs" => options with { Runs = Positive(args, ref i), RunsGiven = true },
                "--process" => options with { Process = true },
                "--differential" => options with { Differential = true },
                "--seed" => options with { Seed = NonNegative(args, ref i) },
                "--program" => options with { Program = NonNegative(args, ref i) },
                "--brand" => options with { Brands = [.. options.Brands, .. Value(args, ref i).Split(',', StringSplitOptions.RemoveEmptyEntries | StringSplitOptions.TrimEntries)] },
                "--restarts" => options with { Restarts = Positive(args, ref i) },
                "--resend" => options with { Resend = true },
                "--rtde-rate" => options with { RtdeRate = true },
                "--twins" => options with { Twins = Positive(args, ref i) },
                "--child-exe" => options with { ChildExecutable = Value(args, ref i) },
                "--native" => options with { NativeTool = Value(args, ref i) },
                "--child-env" => options with { ChildEnvironment = WithVariable(options.ChildEnvironment, Value(args, ref i)) },
                "--warmup" => options with { Warmups = NonNegative(args, ref i) },
                "--scaling" => options with { Scaling = true },
                "--no-scaling" => options with { Scaling = false },
                "--quick" => options with { Quick = true },
                "--json" => options with { Json = true },
                "--list" => options with { List = true },
                "--help" or "-h" or "-?" => options with { Help = true },
                _ => throw new ArgumentException($"Unknown option \"{arg}\"."),
            };
        }
        return options;
    }

    /// <summary>True when the scenario was asked for (all are, when none is named).</summary>
    public bool Selects(Scenario scenario) => Scenarios.Count == 0 || Scenarios.Any(s =>
        scenario.Name.Equals(s, StringComparison.OrdinalIgnoreCase) || scenario.Name.StartsWith(s + "-", StringComparison.OrdinalIgnoreCase));

    private static Dictionary<string, string> WithVariable(Dictionary<string, string> variables, string text)
    {
        string[] parts = text.Split('=', 2);
        if (parts.Length != 2 || parts[0].Length == 0)
        {
            throw new ArgumentException($"--child-env needs NAME=VALUE, not \"{text}\".");
        }
        return new Dictionary<string, string>(variables) { [parts[0]] = parts[1] };
    }

    private static string Value(string[] args, ref int i) =>
        i + 1 < args.Length ? args[++i] : throw new ArgumentException($"Option {args[i]} needs a value.");

    private static int Positive(string[] args, ref int i)
    {
        string name = args[i];
        int value = NonNegative(args, ref i);
        return value > 0 ? value : throw new ArgumentException($"Option {name} needs a number greater than 0.");
    }

    private static int NonNegative(string[] args, ref int i)
    {
        string name = args[i];
        string text = Value(args, ref i).Replace("_", "");
        if (double.TryParse(text, NumberStyles.Float, CultureInfo.InvariantCulture, out double value) && value >= 0 && value <= int.MaxValue && value == Math.Floor(value))
        {
            return (int)value;
        }
        throw new ArgumentException($"Option {name} needs a whole number, not \"{text}\".");
    }
}
