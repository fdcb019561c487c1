namespace Machina.Tests.Control;

/// <summary>
/// An acknowledgement is the busiest report (one per streamed action): handing it to the session's loop allocates nothing (it
/// made a closure and a delegate, about 110 bytes, each time), and acknowledgements are still handled in order.
/// </summary>
public class AcknowledgementAllocationTests
{
    [Fact]
    public void Acknowledge_ManyInFlight_AllocatesNothingPerAcknowledgement_ExecutesInOrder()
    {
        var driver = new FakeDriver();
        Robot bot = OnlineRobot.Create(driver, connect: false);
        bot.BlockSize = 1000;   // every action is released at once: an acknowledgement then only executes
        bot.Connect("127.0.0.1", 7000);
        for (int i = 0; i < 300; i++)
        {
            bot.Move(i % 2 == 0 ? 1 : -1, 0, 0);
        }
        int[] sent = [.. driver.Sent.Select(a => a.Id)];
        Assert.Equal(300, sent.Length);
        for (int i = 0; i < 100; i++)
        {
            driver.Ack(sent[i]);   // warms up the loop (the caller runs it when it is idle, as the link's thread does)
        }

        long before = GC.GetAllocatedBytesForCurrentThread();
        for (int i = 100; i < 300; i++)
        {
            driver.Ack(sent[i]);
        }
        long perAcknowledgement = (GC.GetAllocatedBytesForCurrentThread() - before) / 200;

        Assert.True(perAcknowledgement < 16, $"{perAcknowledgement} bytes per acknowledgement");
        Assert.Empty(bot.GetPendingActions());
        Assert.Equal(0, driver.Unacknowledged);
    }

    [Fact]
    public void Acknowledge_SkippedIds_ExecutesEverythingUpToTheLatest_InOrder()
    {
        var driver = new FakeDriver();
        Robot bot = OnlineRobot.Create(driver);
        var executed = new List<int>();
        bot.ActionExecuted += (_, e) =>
        {
            lock (executed)
            {
                executed.Add(e.LastAction.Id);
            }
        };
        for (int i = 0; i < 5; i++)
        {
            bot.Move(1, 0, 0);
        }
        int[] sent = [.. driver.Sent.Select(a => a.Id)];

        driver.Listener!.OnAcknowledged(sent[1]);   // covers the first
        driver.Listener!.OnAcknowledged(sent[4]);   // covers the third and fourth
        OnlineRobot.Flush(bot);

        Assert.Equal(sent, executed);
        Assert.Empty(bot.GetPendingActions());
    }
}
