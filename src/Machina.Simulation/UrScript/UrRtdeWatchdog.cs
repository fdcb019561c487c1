using System.Globalization;

namespace Machina.Simulation.UrScript;

/// <summary>
/// The RTDE watchdogs a program set with <c>rtde_set_watchdog(variable_name, min_frequency, action)</c>, as the Script Manual
/// describes them: when an RTDE input variable gets no update for a period of 1 / min_frequency, the action is taken —
/// <c>"ignore"</c> (nothing, the pendant notes it), <c>"pause"</c> (the program is held, as the dashboard's <c>pause</c>
/// holds it) or <c>"stop"</c> (the program stops). Every input data package that carries the variable is an update, whatever
/// its value. A watchdog trips once, until its variable is updated again; all of them are removed when the program stops
/// ("All watchdogs are removed on program stop"). A watchdog set again for the same variable replaces it; a frequency of 0
/// removes it. Timed on the controller's <see cref="TimeProvider"/>, so a test's manual clock drives it.
/// </summary>
internal sealed class UrRtdeWatchdog(TimeProvider time, Action<string, string> trip) : IDisposable
{
    private readonly Lock _gate = new();
    private readonly Dictionary<string, Entry> _entries = new(StringComparer.Ordinal);
    private ITimer? _timer;

    private sealed class Entry(double frequency, string action, long lastUpdate)
    {
        public double Frequency { get; } = frequency;

        public string Action { get; } = action;

        public long LastUpdate { get; set; } = lastUpdate;

        public bool Tripped { get; set; }
    }

    /// <summary>The watchdogs set now: variable, minimum frequency (Hz) and action.</summary>
    public IReadOnlyList<(string Variable, double MinFrequency, string Action)> Armed
    {
        get
        {
            lock (_gate)
            {
                return [.. _entries.Select(e => (e.Key, e.Value.Frequency, e.Value.Action))];
            }
        }
    }

    /// <summary><c>rtde_set_watchdog</c>: watches <paramref name="variable"/> from now on (0 Hz removes its watchdog).</summary>
    public void Set(string variable, double frequency, string action)
    {
        lock (_gate)
        {
            if (frequency == 0)
            {
                _entries.Remove(variable);
            }
            else
            {
                _entries[variable] = new Entry(frequency, action, time.GetTimestamp());
            }
            Schedule();
        }
    }

    /// <summary>An RTDE input package carried <paramref name="variable"/>.</summary>
    public void Updated(string variable)
    {
        lock (_gate)
        {
            if (_entries.TryGetValue(variable, out Entry? entry))
            {
                entry.LastUpdate = time.GetTimestamp();
                entry.Tripped = false;
            }
        }
    }

    /// <summary>The program stopped: every watchdog is removed.</summary>
    public void Clear()
    {
        lock (_gate)
        {
            _entries.Clear();
            _timer?.Change(Timeout.InfiniteTimeSpan, Timeout.InfiniteTimeSpan);
        }
    }

    /// <summary>Runs when the earliest watchdog may have run out: trips those that did, then waits for the next.</summary>
    private void Check()
    {
        List<(string Variable, string Action, string Message)> tripped = [];
        lock (_gate)
        {
            long now = time.GetTimestamp();
            foreach ((string variable, Entry entry) in _entries)
            {
                TimeSpan period = TimeSpan.FromSeconds(1 / entry.Frequency);
                if (!entry.Tripped && time.GetElapsedTime(entry.LastUpdate, now) >= period)
                {
                    entry.Tripped = true;
                    string done = entry.Action switch { "pause" => "program paused", "stop" => "program stopped", _ => "ignored" };
                    tripped.Add((variable, entry.Action, string.Create(CultureInfo.InvariantCulture,
                        $"RTDE watchdog: no update of {variable} within {period.TotalSeconds:0.###} s ({entry.Frequency:0.###} Hz): {done}")));
                }
            }
            Schedule();
        }
        foreach ((string variable, string action, string message) in tripped)
        {
            trip(action, message);
        }
    }

    /// <summary>Sets the timer to the earliest deadline of a watchdog not yet tripped (call under the gate).</summary>
    private void Schedule()
    {
        long now = time.GetTimestamp();
        TimeSpan? first = null;
        foreach (Entry entry in _entries.Values.Where(e => !e.Tripped))
        {
            TimeSpan left = TimeSpan.FromSeconds(1 / entry.Frequency) - time.GetElapsedTime(entry.LastUpdate, now);
            first = first is null || left < first ? left : first;
        }
        if (first is null)
        {
            _timer?.Change(Timeout.InfiniteTimeSpan, Timeout.InfiniteTimeSpan);
            return;
        }
        // An update moves the deadline without touching the timer: when it fires early, Check finds nothing run out and waits again.
        // Whole milliseconds up: a system timer drops the fraction and would fire before the deadline.
        TimeSpan due = first.Value > TimeSpan.Zero ? TimeSpan.FromMilliseconds(Math.Ceiling(first.Value.TotalMilliseconds)) : TimeSpan.Zero;
        _timer ??= time.CreateTimer(static s => ((UrRtdeWatchdog)s!).Check(), this, Timeout.InfiniteTimeSpan, Timeout.InfiniteTimeSpan);
        _timer.Change(due, Timeout.InfiniteTimeSpan);
    }

    /// <inheritdoc/>
    public void Dispose()
    {
        lock (_gate)
        {
            _timer?.Dispose();
            _timer = null;
        }
    }
}
