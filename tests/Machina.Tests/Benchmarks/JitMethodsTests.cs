using System.Runtime.CompilerServices;
using Machina.Benchmarks;

namespace Machina.Tests.Benchmarks;

/// <summary>The benchmarks' list of methods the JIT compiled during measured runs (<c>MACHINA_BENCH_JIT=1</c>).</summary>
public class JitMethodsTests
{
    [Theory]
    [InlineData(3, "Tier0")]
    [InlineData(4, "Tier1")]
    [InlineData(5, "Tier1-OSR")]
    [InlineData(6, "Tier0-instr")]
    [InlineData(7, "Tier1-instr")]
    [InlineData(2, "Optimized")]
    [InlineData(0, "unknown")]
    public void Tier_ReadsTheRuntimesOptimisationTier(int tier, string expected)
    {
        Assert.Equal(expected, JitMethods.Tier(tier));
    }

    [Fact]
    public void Drain_WhileCounting_ListsAMethodCompiledForTheFirstTime()
    {
        using var listener = new JitMethods();
        listener.Counting = true;
        Assert.Equal(42, NeverCalledBefore(41));

        // The runtime's events reach the listener on its dispatch thread: look again until they do, within a bound.
        var seen = new List<string>();
        for (int i = 0; i < 200 && !seen.Exists(l => l.Contains(nameof(NeverCalledBefore), StringComparison.Ordinal)); i++)
        {
            Thread.Sleep(50);
            seen.AddRange(listener.Drain(top: 1000));
        }

        Assert.Contains(seen, l => l.Contains(nameof(NeverCalledBefore), StringComparison.Ordinal));
        Assert.StartsWith("  by tier: ", seen[0], StringComparison.Ordinal);
    }

    [Fact]
    public void Drain_WhenNotCounting_ListsNothing()
    {
        using var listener = new JitMethods();
        Assert.Equal(7, NotCountedEither(6));
        Thread.Sleep(200);

        Assert.Equal(["  by tier: "], listener.Drain());
    }

    [MethodImpl(MethodImplOptions.NoInlining)]
    private static int NeverCalledBefore(int x) => x + 1;

    [MethodImpl(MethodImplOptions.NoInlining)]
    private static int NotCountedEither(int x) => x + 1;
}
