using Machina.Simulation.Twin;
using Machina.Tests.Support;

namespace Machina.Tests.Simulation.Twin;

/// <summary>How a twin's thread waits for a task: the result or the task's own exception, a cancellation, the test's clock.</summary>
public class TwinWaitTests
{
    [Fact]
    public void For_ATaskThatCompletesLater_ReturnsItsResult()
    {
        var source = new TaskCompletionSource<int>(TaskCreationOptions.RunContinuationsAsynchronously);
        using var timer = new Timer(_ => source.SetResult(42), null, 50, Timeout.Infinite);
        Assert.Equal(42, TwinWait.For(source.Task, CancellationToken.None));
    }

    [Fact]
    public void For_ATaskThatFails_ThrowsItsException()
    {
        var source = new TaskCompletionSource();
        using var timer = new Timer(_ => source.SetException(new InvalidOperationException("the write failed")), null, 50, Timeout.Infinite);
        var e = Assert.Throws<InvalidOperationException>(() => TwinWait.For(source.Task, CancellationToken.None));
        Assert.Equal("the write failed", e.Message);
    }

    [Fact]
    public void For_CancelledBeforeTheTaskEnds_ThrowsOperationCanceled()
    {
        var never = new TaskCompletionSource<bool>();
        using var cancel = new CancellationTokenSource(50);
        Assert.ThrowsAny<OperationCanceledException>(() => TwinWait.For(never.Task, cancel.Token));
        Assert.False(never.Task.IsCompleted);
    }

    [Fact]
    public async Task Delay_OnATestClock_EndsWhenTheClockReachesIt()
    {
        var clock = new ManualClock();
        Task wait = Task.Run(() => TwinWait.Delay(TimeSpan.FromSeconds(3), clock, CancellationToken.None));
        await Eventually.TrueAsync(() => clock.TimersCreated == 1, "the wait's timer", TimeSpan.FromSeconds(10));
        clock.Advance(TimeSpan.FromSeconds(2));
        await Task.Delay(50);
        Assert.False(wait.IsCompleted);
        clock.Advance(TimeSpan.FromSeconds(1));
        await wait.WaitAsync(TimeSpan.FromSeconds(10));
    }
}
