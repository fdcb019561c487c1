using Machina.Simulation.Twin;
using Machina.Tests.Support;

namespace Machina.Tests.Simulation.Twin;

/// <summary>The clock of a twin that runs faster than real time: motions take the scaled time, a background task's period stays real.</summary>
public class TwinClockTests
{
    private static readonly TimeSpan Bound = TimeSpan.FromSeconds(10);

    [Fact]
    public async Task WaitAside_AtAThousandTimesRealTime_TakesAThousandthOfTheWallTime()
    {
        var wall = new ManualClock();
        var clock = new TwinClock(new TwinScaledTime(wall, 1000), realTime: true);
        Task wait = Task.Run(() => clock.WaitAside(2, CancellationToken.None));
        await Eventually.TrueAsync(() => wall.TimersCreated == 1, "the wait's timer", Bound);
        wall.Advance(TimeSpan.FromMilliseconds(2));
        await wait.WaitAsync(Bound);
        Assert.Equal(0, clock.Seconds); // beside the program: no program time
    }

    [Fact]
    public async Task WaitWall_AtAThousandTimesRealTime_TakesItsWholeTimeOnTheWallClock()
    {
        // A RAPID monitor task's WaitTime: at 1000x it once waited 20 µs instead of 20 ms and sent the state 50,000 times a second.
        var wall = new ManualClock();
        var clock = new TwinClock(new TwinScaledTime(wall, 1000), realTime: true);
        Task wait = Task.Run(() => clock.WaitWall(2, CancellationToken.None));
        await Eventually.TrueAsync(() => wall.TimersCreated == 1, "the wait's timer", Bound);
        wall.Advance(TimeSpan.FromSeconds(1));
        await Task.Delay(50);
        Assert.False(wait.IsCompleted, "the wait ended after 1 s of its 2 s");
        wall.Advance(TimeSpan.FromSeconds(1));
        await wait.WaitAsync(Bound);
        Assert.Equal(0, clock.Seconds);
    }
}
