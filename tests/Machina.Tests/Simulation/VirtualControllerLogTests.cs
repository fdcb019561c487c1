using Machina.Simulation;

namespace Machina.Tests.Simulation;

/// <summary>
/// A virtual controller's logs read "since N": a reader who polls (<c>machina sim</c>'s activity, every 50 ms) copies only what
/// came after its last read, and nothing when nothing did, whether or not the log has dropped its oldest entries.
/// </summary>
public sealed class VirtualControllerLogTests
{
    [Fact]
    public void CopySince_GivesOnlyTheNewEntries_AlsoAfterTheRingDroppedTheOldest()
    {
        var log = new VirtualControllerLog<int>(4);
        var into = new List<int>();
        for (int i = 1; i <= 3; i++)
        {
            log.Add(i);
        }
        Assert.Equal(3, log.CopySince(0, into));
        Assert.Equal([1, 2, 3], into);

        into.Clear();
        for (int i = 4; i <= 10; i++)
        {
            log.Add(i);
        }
        Assert.Equal(10, log.Total);
        Assert.Equal([7, 8, 9, 10], log.ToArray());
        Assert.Equal(10, log.CopySince(3, into)); // more came than it keeps: the kept ones
        Assert.Equal([7, 8, 9, 10], into);

        into.Clear();
        Assert.Equal(10, log.CopySince(8, into));
        Assert.Equal([9, 10], into);

        into.Clear();
        Assert.Equal(10, log.CopySince(10, into));
        Assert.Empty(into);
    }

    [Fact]
    public void CopySince_CapacityZero_KeepsNothingAndStillCounts()
    {
        var log = new VirtualControllerLog<string>(0);
        log.Add("a");
        log.Add("b");
        var into = new List<string>();
        Assert.Equal(2, log.CopySince(0, into));
        Assert.Empty(into);
        Assert.Empty(log.ToArray());
    }

    [Fact]
    public async Task ErrorsSince_OnAController_CopiesWhatCameAfterTheCount_AndNothingWhenNothingDid()
    {
        await using var controller = new VirtualUrController(new VirtualUrControllerOptions { InstantExecution = true });
        await controller.StartAsync();
        var into = new List<string>();
        Assert.Equal(0, controller.ErrorsSince(0, into));
        Assert.Empty(into);

        // Two programs that do not compile: each is an error the controller keeps.
        controller.Twin.Receive("def a():\n  nonsense(\nend\n");
        controller.Twin.Receive("def b():\n  more nonsense(\nend\n");
        long seen = controller.ErrorsSince(0, into);
        Assert.Equal(2, seen);
        Assert.Equal(controller.Errors, into);
        Assert.All(into, e => Assert.StartsWith("Compile error", e, StringComparison.Ordinal));

        into.Clear();
        Assert.Equal(seen, controller.ErrorsSince(seen, into));
        Assert.Empty(into);

        controller.Twin.Receive("def c():\n  third(\nend\n");
        Assert.Equal(3, controller.ErrorsSince(seen, into));
        Assert.Equal([controller.Errors[^1]], into);
    }
}
