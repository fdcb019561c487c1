using Machina.Simulation.Twin;

namespace Machina.Tests.Simulation.Twin;

/// <summary>
/// The signal a virtual controller sets when what it shows changes, and that <c>machina sim</c>'s activity sleeps on: set at
/// first, taken by the reader before it looks, set again by any change after, and a wait armed while it is clear ends at the
/// next change, not before.
/// </summary>
public sealed class TwinChangeSignalTests
{
    private static readonly TimeSpan Bound = TimeSpan.FromSeconds(60);

    [Fact]
    public void Take_SetAtFirst_ClearAfterTaking_SetAgainByAChange()
    {
        var signal = new TwinChangeSignal();
        Assert.True(signal.Take());
        Assert.False(signal.Take());
        signal.Changed();
        signal.ChangedAfterFence(); // a second change while set: still one look
        Assert.True(signal.Take());
        Assert.False(signal.Take());
    }

    [Fact]
    public async Task WhenChangedAsync_WhileClear_EndsAtTheNextChangeOnly()
    {
        var signal = new TwinChangeSignal();
        Assert.True(signal.WhenChangedAsync(CancellationToken.None).IsCompleted); // set at first: the first look is at once
        signal.Take();

        Task waiting = signal.WhenChangedAsync(CancellationToken.None);
        Assert.False(waiting.IsCompleted);
        signal.Changed();
        await waiting.WaitAsync(Bound);
        Assert.True(signal.Take());
    }

    [Fact]
    public async Task WhenChangedAsync_ChangedByAnotherThreadManyTimes_NeverMissesAChange()
    {
        var signal = new TwinChangeSignal();
        for (int round = 0; round < 2_000; round++)
        {
            signal.Take();
            Task waiting = signal.WhenChangedAsync(CancellationToken.None);
            var writer = Task.Run(signal.Changed);
            await waiting.WaitAsync(Bound); // a lost wake-up would hang here until the bound
            await writer;
        }
    }

    [Fact]
    public async Task WhenChangedAsync_Cancelled_EndsWithoutAChange()
    {
        var signal = new TwinChangeSignal();
        signal.Take();
        using var cancel = new CancellationTokenSource();
        Task waiting = signal.WhenChangedAsync(cancel.Token);
        await cancel.CancelAsync();
        await Assert.ThrowsAnyAsync<OperationCanceledException>(() => waiting.WaitAsync(Bound));
        Assert.False(signal.Take());
    }
}
