using Machina.Benchmarks;

namespace Machina.Tests.Benchmarks;

/// <summary>The benchmarks' count of the exceptions thrown during measured runs (<c>MACHINA_BENCH_JIT=1</c>).</summary>
public class JitMethodsExceptionTests
{
    [Fact]
    public void Drain_WhileCounting_CountsEachExceptionThrownOnce_ByTypeAndMessage()
    {
        using var listener = new JitMethods();
        listener.Counting = true;
        string marker = "marker " + Guid.NewGuid().ToString("N");

        // The runtime's events reach the listener on its dispatch thread, and its session may start after the listener: throw
        // again (a new message each time) and look until one arrives, within a bound.
        string? line = null;
        for (int i = 0; i < 200 && line is null; i++)
        {
            try
            {
                throw new InvalidOperationException($"{marker} {i}");
            }
            catch (InvalidOperationException)
            {
            }
            Thread.Sleep(50);
            line = listener.Drain(top: 0).FirstOrDefault(l => l.Contains(marker, StringComparison.Ordinal));
        }

        Assert.NotNull(line);
        Assert.StartsWith("  exceptions thrown: ", line, StringComparison.Ordinal);
        // Each throw once, by type and message; the event that ends a throw (no type) is not counted as another.
        int listed = line.Split(marker).Length - 1;
        int once = line.Split($"; 1 x System.InvalidOperationException: {marker} ").Length - 1;
        Assert.True(listed >= 1);
        Assert.Equal(listed, once);
        Assert.DoesNotContain(" x : ", line, StringComparison.Ordinal);
    }
}
