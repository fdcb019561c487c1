using System.Runtime;

namespace Machina.Benchmarks;

/// <summary>
/// What the JIT compiler did in this process (all threads, <see cref="JitInfo"/>): methods compiled and time spent compiling,
/// tier 0, tier 1, on-stack replacement and PGO's instrumented tier alike. The difference of two readings tells whether a run
/// still paid for compiling: in a steady state it compiles (almost) nothing.
/// </summary>
internal readonly record struct JitActivity(long Methods, TimeSpan Time)
{
    /// <summary>The totals now.</summary>
    public static JitActivity Now() => new(JitInfo.GetCompiledMethodCount(), JitInfo.GetCompilationTime());

    /// <summary>What was compiled since <paramref name="before"/>.</summary>
    public JitActivity Since(JitActivity before) => new(Methods - before.Methods, Time - before.Time);
}
