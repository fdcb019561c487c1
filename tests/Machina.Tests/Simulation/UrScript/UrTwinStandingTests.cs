using Machina.Simulation.UrScript;
using Machina.Tests.Support;

namespace Machina.Tests.Simulation.UrScript;

/// <summary>
/// The wait for the arm to stand (a pause or a stop on the path answers once the hold has stopped the motion in progress):
/// blocking, it ends at once when its cancellation does; awaited, it holds no thread and completes when a hold stops the motion.
/// The motion runs in real time on a manual clock that the test does not advance, so it stays in progress until held.
/// </summary>
public class UrTwinStandingTests
{
    private static readonly TimeSpan Bound = TimeSpan.FromMinutes(1);

    private static (UrTwinController Twin, ManualClock Clock) Moving()
    {
        var clock = new ManualClock();
        var twin = new UrTwinController(new UrTwinOptions { Time = clock, RealTime = true });
        Assert.True(twin.Start("def turn():\n  movej([0.5, -1.5, 1.5, -1.5, -1.5, 0], a=1.4, v=1.05)\nend\n"), twin.Error);
        Assert.True(SpinWait.SpinUntil(() => twin.Motion is not null && clock.PendingTimers == 1, Bound), $"the movej did not start: {twin.State} {twin.Error}");
        return (twin, clock);
    }

    [Fact]
    public void WaitUntilStanding_WhileAMotionRuns_EndsWhenCancelled()
    {
        (UrTwinController twin, _) = Moving();
        using (twin)
        {
            Assert.False(twin.WaitUntilStanding(TimeSpan.Zero)); // moving
            using var cancel = new CancellationTokenSource();
            cancel.Cancel();
            Assert.ThrowsAny<OperationCanceledException>(() => twin.WaitUntilStanding(Timeout.InfiniteTimeSpan, cancel.Token));
            Assert.NotNull(twin.Motion); // the wait ended, not the motion
        }
    }

    [Fact]
    public async Task WaitUntilStandingAsync_CompletesWhenAHoldStopsTheMotion_AndTimesOutWhileItRuns()
    {
        (UrTwinController twin, ManualClock clock) = Moving();
        using (twin)
        {
            Assert.False(await twin.WaitUntilStandingAsync(TimeSpan.Zero, CancellationToken.None)); // moving: the timeout's answer

            Task<bool> standing = twin.WaitUntilStandingAsync(Timeout.InfiniteTimeSpan, CancellationToken.None);
            Assert.False(standing.IsCompleted);
            Assert.True(twin.Hold());
            Assert.True(await standing.WaitAsync(Bound));
            Assert.Null(twin.Motion);
            Assert.True(twin.WaitUntilStanding(TimeSpan.Zero)); // standing: at once
            Assert.True(await twin.WaitUntilStandingAsync(TimeSpan.Zero, CancellationToken.None));

            Assert.True(twin.Release()); // the rest of the movej, then the program ends
            Assert.True(SpinWait.SpinUntil(() => twin.Motion is not null && clock.PendingTimers == 1, Bound), "the movej did not go on");
            clock.Advance(TimeSpan.FromSeconds(60));
            Assert.True(twin.WaitForEnd(Bound));
            Assert.True(twin.State == UrProgramState.Finished, twin.Error);
        }
    }

    [Fact]
    public async Task WaitUntilStandingAsync_WhileAMotionRuns_EndsWhenCancelled()
    {
        (UrTwinController twin, _) = Moving();
        using (twin)
        {
            using var cancel = new CancellationTokenSource();
            Task<bool> standing = twin.WaitUntilStandingAsync(Timeout.InfiniteTimeSpan, cancel.Token);
            Assert.False(standing.IsCompleted);
            cancel.Cancel();
            await Assert.ThrowsAnyAsync<OperationCanceledException>(() => standing.WaitAsync(Bound));
            Assert.NotNull(twin.Motion);
        }
    }
}
