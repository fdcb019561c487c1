namespace Machina.Benchmarks;

/// <summary>
/// One thing to measure. <see cref="Prepare"/> builds the input outside the timed region (a robot with a million moves, a
/// file of instructions…) and returns the work to time; the work returns its result, which is kept alive while the
/// harness measures how much memory it retains.
/// </summary>
internal abstract class Scenario
{
    /// <summary>Short name used on the command line, e.g. <c>compile-abb</c>.</summary>
    public abstract string Name { get; }

    /// <summary>What is measured, in a few words.</summary>
    public abstract string Title { get; }

    /// <summary>What one unit of work is ("action", "line", "pose").</summary>
    public virtual string Unit => "action";

    /// <summary>The size the target is stated for.</summary>
    public abstract int TargetSize { get; }

    /// <summary>The sizes of the scaling table; empty when scaling makes no sense for this scenario.</summary>
    public virtual IReadOnlyList<int> ScalingSizes => [10_000, 100_000, 1_000_000];

    /// <summary>The target, or null when the scenario is informative only.</summary>
    public abstract Target? Target { get; }

    /// <summary>True when the work uses several threads, so allocations are counted for the whole process.</summary>
    public virtual bool MultiThreaded => false;

    /// <summary>Null when the feature is present, else why the scenario cannot run (e.g. a compiler not written yet).</summary>
    public virtual string? Unavailable() => null;

    /// <summary>Builds the input for <paramref name="size"/> units and returns the work to time.</summary>
    public abstract Func<object?> Prepare(int size);

    /// <summary>
    /// After <see cref="Prepare"/>: a run of the work with a few units only, or null (the default). The harness calls it
    /// <c>Runner.OncePerRunRounds</c> x 16 times before the warm-ups, pausing between rounds, so that the code a run calls once
    /// (connecting, disconnecting, <c>SpeedTo</c>, the wait for completion, the twin's accept) crosses both of the JIT's
    /// promotion thresholds (30 calls each) there, and not inside the measured runs, which a row's few warm-ups of the full
    /// size never reach.
    /// </summary>
    public virtual Action? SmallRun() => null;

    /// <summary>Releases what <see cref="Prepare"/> built (temporary files, servers).</summary>
    public virtual void Cleanup() { }
}
