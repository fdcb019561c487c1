using System.Globalization;

namespace Machina.Benchmarks;

/// <summary>
/// Processor time of this process's threads (Linux: <c>/proc/self/task/*/schedstat</c>, nanoseconds on the processor, and the
/// thread's name from <c>stat</c>), to see where a multi-threaded scenario spends it (the host's loop and link, the twin's
/// interpreter threads, the JIT's tiered-compilation thread, the GC). A difference of two readings is taken per thread id, so
/// that a thread that ended and a new one of the same name (a link per connection) do not cancel out; a thread that ended
/// between the readings is missing from it. Empty where /proc is not there.
/// </summary>
internal static class ThreadCpu
{
    /// <summary>The name the runtime gives its tiered-compilation thread, as /proc shows it (15 characters at most).</summary>
    public const string JitThreadName = ".NET Tiered Com";

    /// <summary>One thread's name, processor time (s) and how many times it was put on a processor (wake-ups and preemptions).</summary>
    public readonly record struct ThreadTime(string Name, double Seconds, long Slices);

    /// <summary>Every thread of the process now, by thread id.</summary>
    public static Dictionary<int, ThreadTime> Read()
    {
        var byId = new Dictionary<int, ThreadTime>();
        if (!Directory.Exists("/proc/self/task"))
        {
            return byId;
        }
        foreach (string task in Directory.EnumerateDirectories("/proc/self/task"))
        {
            string stat, schedstat;
            try
            {
                stat = File.ReadAllText(Path.Combine(task, "stat"));
                schedstat = File.ReadAllText(Path.Combine(task, "schedstat"));
            }
            catch (IOException)
            {
                continue;   // the thread ended meanwhile
            }
            int open = stat.IndexOf('('), close = stat.LastIndexOf(')');
            string[] fields = schedstat.Split(' ');
            if (open < 0 || close < open || fields.Length < 3 || !int.TryParse(Path.GetFileName(task), out int id))
            {
                continue;
            }
            // schedstat: nanoseconds on a processor, nanoseconds waiting to run, times run on a processor.
            byId[id] = new ThreadTime(stat[(open + 1)..close], long.Parse(fields[0], CultureInfo.InvariantCulture) / 1e9,
                long.Parse(fields[2], CultureInfo.InvariantCulture));
        }
        return byId;
    }

    /// <summary>What each thread name spent between two readings (threads of one name summed), largest first.</summary>
    public static List<ThreadTime> Difference(Dictionary<int, ThreadTime> before, Dictionary<int, ThreadTime> after) =>
        after.Select(p => before.TryGetValue(p.Key, out ThreadTime b) && b.Name == p.Value.Name
                ? p.Value with { Seconds = p.Value.Seconds - b.Seconds, Slices = p.Value.Slices - b.Slices }
                : p.Value)
            .GroupBy(t => t.Name)
            .Select(g => new ThreadTime(g.Key, g.Sum(t => t.Seconds), g.Sum(t => t.Slices)))
            .Where(t => t.Seconds > 0)
            .OrderByDescending(t => t.Seconds)
            .ToList();

    /// <summary>Processor seconds of the JIT's tiered-compilation thread in a difference (0 when it did not run).</summary>
    public static double Jit(List<ThreadTime> difference) => difference.Where(t => t.Name == JitThreadName).Sum(t => t.Seconds);

    /// <summary>"name 0.123 s, ..." of a difference; with <paramref name="perUnit"/>, also µs per unit and times put on a processor per unit.</summary>
    public static string Text(List<ThreadTime> difference, int perUnit = 0) => string.Join(", ", difference
        .Where(t => t.Seconds >= 0.0005)
        .Select(t => perUnit > 0
            ? string.Create(CultureInfo.InvariantCulture, $"{t.Name} {t.Seconds:0.000} s ({t.Seconds * 1e6 / perUnit:0.0} us, {(double)t.Slices / perUnit:0.00} runs/unit)")
            : string.Create(CultureInfo.InvariantCulture, $"{t.Name} {t.Seconds:0.000} s")));
}
