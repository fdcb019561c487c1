using System.Diagnostics;

namespace Machina.Benchmarks.Differential;

/// <summary>
/// The benchmark-sized differential run (<c>--differential</c>): for each brand with a driver, every sample program and N seeded
/// random programs, compiled and run on the twin and streamed online to the same twin (<see cref="DifferentialCheck"/>). Prints
/// the counts per brand and every disagreement with its seed; exit code 1 when there is one.
/// </summary>
internal static class DifferentialSuite
{
    /// <summary>The seed of random program <paramref name="index"/> of a run started at <paramref name="seed"/>.</summary>
    internal static int SeedOf(int seed, int index) => unchecked(seed * 1_000_003 + index);

    /// <summary>Runs the property; <paramref name="brands"/> empty means ABB, UR and KUKA.</summary>
    internal static int Run(int programs, int seed, IReadOnlyList<string> brands, TextWriter output)
    {
        RobotType[] selected = Selected(brands);
        string? samples = SamplesFolder();
        output.WriteLine($"Differential run: {programs} random programs per brand from seed {seed}, and the sample programs in {samples ?? "(not found)"}.");
        bool disagreed = false;
        foreach (RobotType brand in selected)
        {
            var counts = new Dictionary<DifferentialVerdict, int>();
            var refusedVerbs = new Dictionary<string, int>();
            var stopReasons = new Dictionary<string, (int Count, string First)>();
            var clock = Stopwatch.StartNew();
            IEnumerable<(string Name, string Text)> all = (samples is null ? [] : Directory.GetFiles(samples, "*.machina").Order(StringComparer.Ordinal)
                    .Select(f => (Path.GetFileName(f), File.ReadAllText(f))))
                .Concat(Enumerable.Range(0, programs).Select(i => ($"seed {SeedOf(seed, i)}", DifferentialPrograms.Random(brand, SeedOf(seed, i)))));
            foreach ((string name, string text) in all)
            {
                DifferentialCheck.Result result;
                try
                {
                    result = DifferentialCheck.RunAsync(brand, text, CancellationToken.None).GetAwaiter().GetResult();
                }
                catch (Exception ex) when (ex is not OutOfMemoryException)
                {
                    result = new DifferentialCheck.Result(DifferentialVerdict.Disagreed, $"the harness failed: {ex}", null, null);
                }
                counts[result.Verdict] = counts.GetValueOrDefault(result.Verdict) + 1;
                if (result.Verdict == DifferentialVerdict.Refused)
                {
                    string verb = result.Verb ?? "?";
                    refusedVerbs[verb] = refusedVerbs.GetValueOrDefault(verb) + 1;
                }
                if (result.Verdict == DifferentialVerdict.Stopped && result.Offline?.Why is string why)
                {
                    string reason = ReasonOf(why);
                    (int count, string first) = stopReasons.GetValueOrDefault(reason, (0, name));
                    stopReasons[reason] = (count + 1, first);
                }
                if (result.Verdict == DifferentialVerdict.Disagreed)
                {
                    disagreed = true;
                    output.WriteLine($"  DISAGREE {brand} {name}: {result.Detail}");
                }
            }
            int total = counts.Values.Sum();
            output.WriteLine($"{brand}: {total} programs in {clock.Elapsed.TotalSeconds:0} s: " +
                $"{counts.GetValueOrDefault(DifferentialVerdict.Finished)} agreed to the end, {counts.GetValueOrDefault(DifferentialVerdict.Stopped)} agreed stopped by the controller, " +
                $"{counts.GetValueOrDefault(DifferentialVerdict.Unreachable)} agreed unreachable (pre-check), {counts.GetValueOrDefault(DifferentialVerdict.Refused)} refused by the pre-check, " +
                $"{counts.GetValueOrDefault(DifferentialVerdict.Disagreed)} disagreements.");
            if (refusedVerbs.Count > 0)
            {
                output.WriteLine($"  refused verbs: {string.Join(", ", refusedVerbs.OrderByDescending(p => p.Value).Select(p => $"{p.Key} {p.Value}"))}");
            }
            if (stopReasons.Count > 0)
            {
                output.WriteLine($"  stopped by: {string.Join(", ", stopReasons.OrderByDescending(p => p.Value.Count).Select(p => $"{p.Key} {p.Value.Count} (first: {p.Value.First})"))}");
            }
            output.Flush();
        }
        return disagreed ? 1 : 0;
    }

    /// <summary>What stopped a compiled program, without its details: the controller's words up to the first colon or parenthesis.</summary>
    private static string ReasonOf(string why)
    {
        int end = why.IndexOfAny([':', '(']);
        return (end > 0 ? why[..end] : why).Trim();
    }

    /// <summary>The program of <paramref name="seed"/> for each selected brand, its verdict and both runs' steps.</summary>
    internal static int Show(int seed, IReadOnlyList<string> brands, TextWriter output)
    {
        bool disagreed = false;
        foreach (RobotType brand in Selected(brands))
        {
            string program = DifferentialPrograms.Random(brand, seed);
            DifferentialCheck.Result result = DifferentialCheck.RunAsync(brand, program, CancellationToken.None).GetAwaiter().GetResult();
            disagreed |= result.Verdict == DifferentialVerdict.Disagreed;
            output.WriteLine($"{brand} seed {seed}:\n{program}{result.Verdict}: {result.Detail}");
            foreach ((string side, TwinRun? run) in new[] { ("compiled", result.Offline), ("streamed", result.Online) })
            {
                output.WriteLine($"  {side}: {run?.End} {run?.Why}");
                foreach (Machina.Simulation.Twin.TwinTraceEntry e in run?.Steps ?? [])
                {
                    output.WriteLine($"    line {e.Line} {e.Text}: TCP {e.Tcp.Position} {e.Tcp.Rotation.ToQuaternionString()}, joints {e.Joints}");
                }
            }
        }
        return disagreed ? 1 : 0;
    }

    private static RobotType[] Selected(IReadOnlyList<string> brands) =>
        [.. DifferentialPrograms.Brands.Where(b => brands.Count == 0 || brands.Any(n => n.Equals(b.ToString(), StringComparison.OrdinalIgnoreCase)))];

    /// <summary>samples/programs of the repository this runs in (looked for upwards from the working directory and the binary).</summary>
    internal static string? SamplesFolder()
    {
        foreach (string from in new[] { Directory.GetCurrentDirectory(), AppContext.BaseDirectory })
        {
            for (DirectoryInfo? d = new(from); d is not null; d = d.Parent)
            {
                string candidate = Path.Combine(d.FullName, "samples", "programs");
                if (Directory.Exists(candidate))
                {
                    return candidate;
                }
            }
        }
        return null;
    }
}
