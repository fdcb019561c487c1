namespace Machina.Tests.Support;

/// <summary>Waiting for what another thread makes true, bounded in real time: tests wait for the condition they assert, never a fixed time.</summary>
internal static class Eventually
{
    /// <summary>Checks <paramref name="condition"/> every few milliseconds; fails the test naming <paramref name="what"/> after <paramref name="limit"/>.</summary>
    internal static async Task TrueAsync(Func<bool> condition, string what, TimeSpan limit)
    {
        long start = TimeProvider.System.GetTimestamp();
        while (!condition())
        {
            if (TimeProvider.System.GetElapsedTime(start) > limit)
            {
                Assert.Fail($"Timed out waiting for {what}.");
            }
            await Task.Delay(5);
        }
    }
}
