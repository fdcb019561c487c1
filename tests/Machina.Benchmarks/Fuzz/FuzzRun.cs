using System.Diagnostics;
using System.Globalization;

namespace Machina.Benchmarks.Fuzz;

/// <summary>What a fuzz run of one language saw.</summary>
internal sealed class FuzzReport(string language)
{
    /// <summary>ur, rapid or krl.</summary>
    public string Language { get; } = language;

    /// <summary>The cases run.</summary>
    public int Cases { get; set; }

    /// <summary>How many cases ended each way (refused, finished, failed: step budget, …).</summary>
    public SortedDictionary<string, int> Outcomes { get; } = new(StringComparer.Ordinal);

    /// <summary>Cases that ended with an exception that is not the program's error: the interpreter's bugs.</summary>
    public List<string> Crashes { get; } = [];

    /// <summary>A case that did not end within its deadline and the grace after it (the run stops there), or null.</summary>
    public string? Hang { get; set; }

    /// <summary>Cases that stopped more than <see cref="FuzzRun.Overrun"/> after their deadline (not hangs: within the grace).</summary>
    public List<string> Overruns { get; } = [];

    /// <summary>The longest case, in milliseconds.</summary>
    public double LongestCaseMs { get; set; }

    /// <summary>The process's peak working set at the end of the language's cases, in bytes.</summary>
    public long PeakWorkingSet { get; set; }

    /// <summary>The largest managed heap seen between cases, in bytes.</summary>
    public long LargestHeap { get; set; }

    /// <summary>The wall time of the run, in seconds.</summary>
    public double Seconds { get; set; }

    /// <summary>One line per outcome and the totals.</summary>
    public override string ToString() => string.Create(CultureInfo.InvariantCulture,
        $"{Language}: {Cases:N0} cases in {Seconds:0.0} s; {string.Join(", ", Outcomes.Select(o => $"{o.Key} {o.Value:N0}"))}; crashes {Crashes.Count}, overruns {Overruns.Count}, " +
        $"hang {(Hang is null ? "none" : "YES")}; longest case {LongestCaseMs:0} ms; largest heap {LargestHeap / 1048576.0:0} MB; peak working set {PeakWorkingSet / 1048576.0:0} MB");
}

/// <summary>
/// Runs fuzz cases of one language on a worker thread with a 1 MB stack (the smallest default among the hosts: a Windows main
/// thread), each with a deadline (its cancellation) and a grace after it: a case that outlives both is a hang.
/// </summary>
internal static class FuzzRun
{
    /// <summary>Each case's cancellation deadline.</summary>
    public static readonly TimeSpan Deadline = TimeSpan.FromSeconds(2);

    /// <summary>How long after its deadline a case may take to stop before it is listed as an overrun (a wait or loop that ignores the cancellation).</summary>
    public static readonly TimeSpan Overrun = TimeSpan.FromSeconds(1);

    /// <summary>How long after its deadline a case may take to stop before it counts as a hang.</summary>
    public static readonly TimeSpan Grace = TimeSpan.FromSeconds(30);

    /// <summary>Runs <paramref name="cases"/> cases of <paramref name="language"/> from <paramref name="seed"/>; failing programs go to <paramref name="saveTo"/> when given.</summary>
    public static FuzzReport Run(FuzzLanguage language, int cases, int seed, string? saveTo = null, TextWriter? progress = null)
    {
        var report = new FuzzReport(language.Name);
        var mutator = new FuzzMutator(new Random(seed), language.Tokens, language.Generate);
        var work = new BlockingSlot();
        var worker = new Thread(() => work.Serve(language), 1024 * 1024) { IsBackground = true, Name = "fuzz " + language.Name };
        worker.Start();
        var total = Stopwatch.StartNew();
        for (int i = 0; i < cases; i++)
        {
            string program = mutator.Next(language.Seeds);
            long started = Stopwatch.GetTimestamp();
            work.Post(program);
            if (!work.Wait(Deadline + Grace, out string? outcome, out Exception? error))
            {
                report.Hang = Save(saveTo, language.Name, i, "hang", program);
                report.Cases = i + 1;
                break;
            }
            TimeSpan took = Stopwatch.GetElapsedTime(started);
            report.LongestCaseMs = Math.Max(report.LongestCaseMs, took.TotalMilliseconds);
            if (took > Deadline + Overrun)
            {
                report.Overruns.Add(string.Create(CultureInfo.InvariantCulture, $"case {i}: {took.TotalSeconds:0.0} s {Save(saveTo, language.Name, i, "overrun", program)}"));
            }
            if (error is not null)
            {
                string where = error.StackTrace?.Split('\n').FirstOrDefault()?.Trim() ?? "";
                report.Crashes.Add($"case {i}: {error.GetType().Name}: {error.Message} {where} {Save(saveTo, language.Name, i, "crash", program)}");
                outcome = "CRASH";
            }
            report.Outcomes[outcome!] = report.Outcomes.GetValueOrDefault(outcome!) + 1;
            report.Cases = i + 1;
            if (i % 256 == 0)
            {
                report.LargestHeap = Math.Max(report.LargestHeap, GC.GetTotalMemory(false));
            }
            if (progress is not null && (i + 1) % 5000 == 0)
            {
                progress.WriteLine($"  {language.Name}: {i + 1:N0} cases, {report.Crashes.Count} crashes, {total.Elapsed.TotalSeconds:0} s");
            }
        }
        work.Stop();
        report.Seconds = total.Elapsed.TotalSeconds;
        using Process self = Process.GetCurrentProcess();
        report.PeakWorkingSet = self.PeakWorkingSet64;
        return report;
    }

    private static string Save(string? folder, string language, int index, string kind, string program)
    {
        if (folder is null)
        {
            return "";
        }
        Directory.CreateDirectory(folder);
        string file = Path.Combine(folder, $"{language}-{kind}-{index}.txt");
        File.WriteAllText(file, program);
        return file;
    }

    /// <summary>Hands one program at a time to the worker thread and its outcome back.</summary>
    private sealed class BlockingSlot
    {
        private readonly object _gate = new();
        private string? _program;
        private string? _outcome;
        private Exception? _error;
        private bool _done;
        private bool _stop;

        public void Post(string program)
        {
            lock (_gate)
            {
                _program = program;
                _done = false;
                Monitor.PulseAll(_gate);
            }
        }

        public bool Wait(TimeSpan timeout, out string? outcome, out Exception? error)
        {
            lock (_gate)
            {
                long end = Environment.TickCount64 + (long)timeout.TotalMilliseconds;
                while (!_done)
                {
                    long left = end - Environment.TickCount64;
                    if (left <= 0 || !Monitor.Wait(_gate, (int)left) && !_done)
                    {
                        outcome = null;
                        error = null;
                        return false;
                    }
                }
                outcome = _outcome;
                error = _error;
                return true;
            }
        }

        public void Stop()
        {
            lock (_gate)
            {
                _stop = true;
                Monitor.PulseAll(_gate);
            }
        }

        public void Serve(FuzzLanguage language)
        {
            while (true)
            {
                string program;
                lock (_gate)
                {
                    while (_program is null && !_stop)
                    {
                        Monitor.Wait(_gate);
                    }
                    if (_stop)
                    {
                        return;
                    }
                    program = _program!;
                    _program = null;
                }
                string? outcome = null;
                Exception? error = null;
                try
                {
                    using var deadline = new CancellationTokenSource(Deadline);
                    outcome = language.Run(program, deadline.Token);
                }
                catch (OperationCanceledException)
                {
                    outcome = "stopped";
                }
                catch (Exception e)
                {
                    error = e;
                }
                lock (_gate)
                {
                    _outcome = outcome;
                    _error = error;
                    _done = true;
                    Monitor.PulseAll(_gate);
                }
            }
        }
    }
}
