using System.Diagnostics;
using Machina.Simulation.Twin;

namespace Machina.Tests.Simulation.Twin;

/// <summary>What a program waiting on the controller's IO sleeps on: a change wakes it, a timeout ends the wait, a cancellation throws.</summary>
public class TwinIoTests
{
    [Fact]
    public void WaitForChange_AChangeFromAnotherThread_WakesTheWaiterBeforeItsTimeout()
    {
        var io = new TwinIo();
        long version = io.Version;
        using var timer = new Timer(_ => io.Changed(), null, 50, Timeout.Infinite);
        var watch = Stopwatch.StartNew();

        Assert.True(io.WaitForChange(version, TimeSpan.FromSeconds(30), CancellationToken.None));
        Assert.True(watch.Elapsed < TimeSpan.FromSeconds(20), $"woken after {watch.Elapsed}");
        Assert.Equal(version + 1, io.Version);
    }

    [Fact]
    public void WaitForChange_AVersionAlreadyPassed_ReturnsAtOnce_NothingChanging_ReturnsFalseAfterTheTimeout()
    {
        var io = new TwinIo();
        long before = io.Version;
        io.Changed();

        Assert.True(io.WaitForChange(before, TimeSpan.Zero, CancellationToken.None));
        var watch = Stopwatch.StartNew();
        Assert.False(io.WaitForChange(io.Version, TimeSpan.FromMilliseconds(30), CancellationToken.None));
        Assert.True(watch.Elapsed >= TimeSpan.FromMilliseconds(25), $"returned after {watch.Elapsed}");
    }

    [Fact]
    public void WaitForChange_Cancelled_Throws()
    {
        var io = new TwinIo();
        using var cancel = new CancellationTokenSource(TimeSpan.FromMilliseconds(50));

        Assert.ThrowsAny<OperationCanceledException>(() => io.WaitForChange(io.Version, TimeSpan.FromSeconds(30), cancel.Token));
    }
}
