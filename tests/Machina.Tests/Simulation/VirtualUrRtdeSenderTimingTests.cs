using System.Diagnostics;
using Machina.Simulation;

namespace Machina.Tests.Simulation;

/// <summary>The virtual UR's RTDE sender: its wait on the system clock, and the in-twin diagnostic of its lateness (issue 45).</summary>
public class VirtualUrRtdeSenderTimingTests
{
    [Fact]
    public void OnLinux_TheSystemClocksWait_EndsAtTheDeadline_NeverBeforeIt()
    {
        if (!OperatingSystem.IsLinux())
        {
            return; // elsewhere the wait counts whole milliseconds and ends up to half of one early, as before
        }
        var wait = new VirtualUrDeadlineWait(TimeProvider.System);
        wait.OnWaitingThread();
        Assert.True(wait.Precise);
        Assert.Equal(TimeSpan.Zero, wait.Early); // a package is due at its deadline, not half a millisecond before
        for (int i = 0; i < 20; i++)
        {
            // 1.3 to 8.9 ms ahead: below, at and above the last stretch that is slept to the microsecond
            long deadline = Stopwatch.GetTimestamp() + (long)(Stopwatch.Frequency * (0.0013 + (0.0004 * i)));
            Assert.False(wait.WaitUntil(deadline, CancellationToken.None));
            long late = Stopwatch.GetTimestamp() - deadline;
            // The millisecond wait ended up to 0.5 ms before the deadline; this one ends after it (how long after depends on the load).
            Assert.True(late >= 0, $"wait {i} ended {-late * 1e6 / Stopwatch.Frequency:0} us before its deadline");
        }
    }

    [Fact]
    public async Task AWake_EndsTheWaitAtOnce_WhileTheDeadlineIsFarAway()
    {
        var wait = new VirtualUrDeadlineWait(TimeProvider.System);
        long deadline = Stopwatch.GetTimestamp() + (5 * Stopwatch.Frequency);
        Task<bool> waiting = Task.Factory.StartNew(() => wait.WaitUntil(deadline, CancellationToken.None), CancellationToken.None, TaskCreationOptions.LongRunning, TaskScheduler.Default);
        await Task.Delay(20);
        wait.Wake();
        Assert.True(await waiting.WaitAsync(TimeSpan.FromSeconds(4)));
        Assert.True(Stopwatch.GetTimestamp() < deadline);
    }

    [Fact]
    public void TheDiagnostic_CountsLatenessByCollection_InPercentilesOfTenMicroseconds()
    {
        using var timing = new VirtualUrRtdeTiming(1_000_000, null); // a clock of microseconds
        for (int i = 0; i < 98; i++)
        {
            timing.Record(100, collected: false);
        }
        timing.Record(-300, collected: false); // half a millisecond wait's early package
        timing.Record(5000, collected: true);
        string summary = timing.Summary();
        Assert.Contains("all: 100 packages, p50 110, p90 110, p99 110, p99.9 5010, late > 0.5 ms 1, > 1 ms 1, > 2 ms 1; ", summary);
        Assert.Contains("no GC during the wait: 99 packages, p50 110, ", summary);
        Assert.Contains("GC during the wait: 1 packages, p50 5010, ", summary);
        Assert.Contains("max 5000 us; woken early 0; ", summary);
    }
}
