using System.Text;
using Machina.Simulation.Rapid;

namespace Machina.Tests.Simulation.Rapid;

/// <summary>
/// The RAPID twin's received-and-unread text (<see cref="RapidInbox"/>): every take delivers exactly the bytes a queue of what
/// arrived delivers, across many interleavings of arrivals and reads (fixed seeds, no threads), and a take that needs a count
/// (<c>\ReadNoOfBytes</c>) takes nothing until the count is held.
/// </summary>
public class RapidInboxTests
{
    [Theory]
    [InlineData(1)]
    [InlineData(2)]
    [InlineData(3)]
    [InlineData(4)]
    [InlineData(5)]
    [InlineData(6)]
    [InlineData(7)]
    [InlineData(8)]
    public void TryTake_ManyInterleavings_DeliversExactlyWhatAQueueDelivers(int seed)
    {
        var random = new Random(seed);
        var inbox = new RapidInbox();
        var model = new StringBuilder();
        int next = 0;
        int takes = 0;
        for (int step = 0; step < 4000; step++)
        {
            if (random.Next(3) == 0)
            {
                // An arrival: 0..3000 characters (a driver's backlog of ~40 requests), numbered so that a misplaced byte shows.
                int length = random.Next(4) == 0 ? random.Next(1000, 3000) : random.Next(0, 200);
                var text = new StringBuilder(length);
                for (int i = 0; i < length; i++)
                {
                    text.Append((char)(' ' + (next++ % 90)));
                }
                inbox.Add(text.ToString());
                model.Append(text);
                Assert.Equal(model.Length, inbox.Count);
                continue;
            }
            int max = random.Next(3) switch { 0 => 80, 1 => 1024, _ => random.Next(1, 200) };
            int least = random.Next(4) == 0 ? random.Next(1, max + 1) : 1;
            string? taken = inbox.TryTake(max, least, out Task arrival);
            if (model.Length >= least)
            {
                int n = Math.Min(max, model.Length);
                Assert.Equal(model.ToString(0, n), taken);
                Assert.True(arrival.IsCompleted);
                model.Remove(0, n);
                takes++;
            }
            else
            {
                Assert.Null(taken);
                Assert.False(arrival.IsCompleted);
            }
            Assert.Equal(model.Length, inbox.Count);
        }
        Assert.True(takes > 1000, $"only {takes} takes");
        inbox.Close();
        while (model.Length > 0)
        {
            int n = Math.Min(80, model.Length);
            Assert.Equal(model.ToString(0, n), inbox.TryTake(80, out _));
            model.Remove(0, n);
        }
        Assert.Equal("", inbox.TryTake(80, out _));
    }

    [Fact]
    public void TryTake_WithACount_TakesNothingUntilTheCountIsHeld_AndArrivalWakesOnlyThen()
    {
        var inbox = new RapidInbox();
        inbox.Add("ab");

        Assert.Null(inbox.TryTake(80, 5, out Task arrival));
        inbox.Add("c");
        bool wokeEarly = arrival.IsCompleted;
        inbox.Add("de");
        bool wokeAtCount = arrival.IsCompleted;
        string? taken = inbox.TryTake(5, 5, out _);

        Assert.False(wokeEarly);
        Assert.True(wokeAtCount);
        Assert.Equal("abcde", taken);
        Assert.Equal(0, inbox.Count);
    }

    [Fact]
    public void TryTake_WithACount_ClosedBeforeTheCount_ReportsClosedAndKeepsTheBytes()
    {
        var inbox = new RapidInbox();
        inbox.Add("xyz");

        Assert.Null(inbox.TryTake(80, 4, out Task arrival));
        inbox.Close();

        Assert.True(arrival.IsCompleted);
        Assert.Equal("", inbox.TryTake(80, 4, out _));
        Assert.Equal("xyz", inbox.TryTake(80, 1, out _));
        Assert.Equal("", inbox.TryTake(80, 1, out _));
    }
}
