using Machina.Benchmarks;

namespace Machina.Tests.Benchmarks;

/// <summary>The benchmarks' count of the exceptions thrown during measured runs (<c>MACHINA_BENCH_JIT=1</c>).</summary>
public class JitMethodsExceptionTests
{
    [Fact]
    public void Drain_WhileCounting_CountsAnExceptionThrownOnce_ByTypeAndMessage()
    {
        using var listener = new JitMethods();
        listener.Counting = true;
        string marker = "marker " + Guid.NewGuid().ToString("N");
        try
        {
            throw new InvalidOperationException(marker);
        }
        catch (InvalidOperationException)
        {
        }

        // The runtime's events reach the listener on its dispatch thread: look again until they do, within a bound.
        string? line = null;
        for (int i = 0; i < 200 && line is null; i++)
        {
            Thread.Sleep(50);
            line = listener.Drain(top: 0).FirstOrDefault(l => l.Contains(marker, StringComparison.Ordinal));
        }

        Assert.NotNull(line);
        // Once, although the runtime writes an event at the throw's start and another at its end.
        Assert.Contains($"; 1 x System.InvalidOperationException: {marker}", line, StringComparison.Ordinal);
        Assert.StartsWith("  exceptions thrown: ", line, StringComparison.Ordinal);
    }
}
