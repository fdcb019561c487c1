namespace Machina.Tests.Support;

/// <summary>Waiting for what another thread makes true, bounded in real time: tests wait for the condition they assert, never a fixed time.</summary>
internal static class Eventually
{
    /// <summary>Checks <paramref name="condition"/> every few milliseconds; fails the test naming <paramref name="what"/> after <paramref name="limit"/>.</summary>
    internal static Task TrueAsync(Func<bool> condition, string what, TimeSpan limit) => TrueAsync(condition, what, limit, static () => "");

    /// <summary>As <see cref="TrueAsync(Func{bool}, string, TimeSpan)"/>; a timeout's message ends with what <paramref name="detail"/> says then.</summary>
    internal static async Task TrueAsync(Func<bool> condition, string what, TimeSpan limit, Func<string> detail)
    {
        long start = TimeProvider.System.GetTimestamp();
        while (!condition())
        {
            if (TimeProvider.System.GetElapsedTime(start) > limit)
            {
                string more = detail();
                Assert.Fail($"Timed out waiting for {what}." + (more.Length > 0 ? " " + more : ""));
            }
            await Task.Delay(5);
        }
    }
}
