using System.Globalization;

namespace Machina.Benchmarks;

/// <summary>
/// Processor time of this process's threads, grouped by thread name (Linux: /proc/self/task/*/stat, user + system ticks), to
/// see where a multi-threaded scenario spends it (the host's loop and sockets, the twin's interpreter threads, the GC).
/// Threads that ended between two readings are missing from the difference; empty where /proc is not there.
/// </summary>
internal static class ThreadCpu
{
    /// <summary>Clock ticks per second of /proc's times (USER_HZ, 100 on Linux).</summary>
    private const double TicksPerSecond = 100;

    /// <summary>Processor seconds per thread name now.</summary>
    public static Dictionary<string, double> Read()
    {
        var byName = new Dictionary<string, double>(StringComparer.Ordinal);
        if (!Directory.Exists("/proc/self/task"))
        {
            return byName;
        }
        foreach (string task in Directory.EnumerateDirectories("/proc/self/task"))
        {
            string stat;
            try
            {
                stat = File.ReadAllText(Path.Combine(task, "stat"));
            }
            catch (IOException)
            {
                continue;   // the thread ended meanwhile
            }
            int open = stat.IndexOf('('), close = stat.LastIndexOf(')');
            if (open < 0 || close < open)
            {
                continue;
            }
            string name = stat[(open + 1)..close];
            string[] fields = stat[(close + 2)..].Split(' ');
            // After the name: state (0), ..., utime (11), stime (12).
            double seconds = (long.Parse(fields[11], CultureInfo.InvariantCulture) + long.Parse(fields[12], CultureInfo.InvariantCulture)) / TicksPerSecond;
            byName[name] = byName.GetValueOrDefault(name) + seconds;
        }
        return byName;
    }

    /// <summary>"name 1.23 s, ..." of what each thread name spent between two readings, largest first.</summary>
    public static string Difference(Dictionary<string, double> before, Dictionary<string, double> after) => string.Join(", ",
        after.Select(p => (p.Key, Seconds: p.Value - before.GetValueOrDefault(p.Key)))
            .Where(p => p.Seconds > 0)
            .OrderByDescending(p => p.Seconds)
            .Select(p => $"{p.Key} {p.Seconds.ToString("0.00", CultureInfo.InvariantCulture)} s"));
}
