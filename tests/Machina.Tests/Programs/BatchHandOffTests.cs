namespace Machina.Tests.Programs;

/// <summary>The queue between an instruction file's reading thread and the compiler: order, its bound, its end and cancellation.</summary>
public class BatchHandOffTests
{
    private static readonly TimeSpan Bound = TimeSpan.FromSeconds(10);

    [Fact]
    public async Task Items_ComeOutInOrder_ThenFalseOnceCompleteAndEmpty()
    {
        using var stop = new CancellationTokenSource();
        using var queue = new BatchHandOff<string>(2, stop.Token);
        Task producer = Task.Run(() =>
        {
            for (int i = 0; i < 100; i++)
            {
                queue.Add("item " + i);
            }
            queue.Complete();
        });
        var taken = new List<string>();
        while (queue.TryTake(out string item, CancellationToken.None))
        {
            taken.Add(item);
        }
        await producer.WaitAsync(Bound);
        Assert.Equal(Enumerable.Range(0, 100).Select(i => "item " + i), taken);
        Assert.False(queue.TryTake(out _, CancellationToken.None));
    }

    [Fact]
    public async Task Add_WhenFull_WaitsUntilAnItemIsTaken()
    {
        using var stop = new CancellationTokenSource();
        using var queue = new BatchHandOff<string>(2, stop.Token);
        queue.Add("a");
        queue.Add("b");
        using var started = new ManualResetEventSlim();
        Task third = Task.Run(() =>
        {
            started.Set();
            queue.Add("c");
        });
        Assert.True(started.Wait(Bound));
        // While the queue is full the third item cannot be in: it stays pending however long we look.
        Assert.NotSame(third, await Task.WhenAny(third, Task.Delay(100)));
        Assert.True(queue.TryTake(out string first, CancellationToken.None));
        await third.WaitAsync(Bound);
        queue.Complete();
        Assert.Equal("a", first);
        Assert.True(queue.TryTake(out string second, CancellationToken.None));
        Assert.True(queue.TryTake(out string last, CancellationToken.None));
        Assert.Equal(("b", "c"), (second, last));
    }

    [Fact]
    public async Task Stop_WakesAWaitingAdd_AndAWaitingTake()
    {
        using var stop = new CancellationTokenSource();
        using var full = new BatchHandOff<string>(1, stop.Token);
        using var empty = new BatchHandOff<string>(1, stop.Token);
        full.Add("a");
        Task adding = Task.Run(() => full.Add("b"));
        Task taking = Task.Run(() => empty.TryTake(out _, stop.Token));
        Task delay = Task.Delay(100);
        Assert.Same(delay, await Task.WhenAny(adding, taking, delay));
        stop.Cancel();
        await Assert.ThrowsAnyAsync<OperationCanceledException>(() => adding.WaitAsync(Bound));
        await Assert.ThrowsAnyAsync<OperationCanceledException>(() => taking.WaitAsync(Bound));
    }
}
