namespace Machina.Tests.Control;

/// <summary>
/// What <see cref="ActionExecutedArgs.PendingExecutionTotal"/> counts: the actions issued so far (when the controller reported
/// this one done) and not executed yet. It is not the rest of a program the robot cannot know: it grows again when more
/// actions are issued after an execution, which is why a program issued while the controller runs sees 0, then 3, then 2.
/// </summary>
public sealed class ExecutedCountTests
{
    private static readonly TimeSpan Limit = TimeSpan.FromMinutes(1);

    [Fact]
    public async Task PendingExecutionTotal_CountsTheIssuedActionsNotExecutedYet_AndGrowsWhenMoreAreIssued()
    {
        var driver = new FakeDriver();
        Robot bot = OnlineRobot.Create(driver);
        var executed = new List<(int Id, int OnDevice, int Total)>();
        bot.ActionExecuted += (_, e) => executed.Add((e.LastAction.Id, e.PendingExecutionOnDevice, e.PendingExecutionTotal));

        bot.MoveTo(400, 0, 400);                 // 1
        await ExecuteAsync(bot, driver, 1);                 // nothing else issued yet: 0 left
        bot.Move(10, 0, 0);                      // 2
        bot.Move(0, 10, 0);                      // 3
        bot.Move(-10, 0, 0);                     // 4
        bot.Move(0, -10, 0);                     // 5
        await ExecuteAsync(bot, driver, 2);                 // 3, 4 and 5 issued and not executed
        bot.Move(0, 0, 10);                      // 6
        await ExecuteAsync(bot, driver, 3);                 // 4, 5 and 6
        await ExecuteAsync(bot, driver, 4);
        await ExecuteAsync(bot, driver, 5);
        await ExecuteAsync(bot, driver, 6);

        // With the default window (8 actions a block) every issued action was sent at once: on the device = total.
        Assert.Equal([(1, 0, 0), (2, 3, 3), (3, 3, 3), (4, 2, 2), (5, 1, 1), (6, 0, 0)], executed);
        await bot.WaitForCompletionAsync().WaitAsync(Limit);
    }

    [Fact]
    public async Task PendingExecutionTotal_CountsActionsStillWaitingToBeSent_PendingExecutionOnDeviceOnlyTheSentOnes()
    {
        var driver = new FakeDriver();
        Robot bot = OnlineRobot.Create(driver);
        bot.BlockSize = 2;
        bot.PendingCount = 1;
        var executed = new List<(int Id, int OnDevice, int Total)>();
        bot.ActionExecuted += (_, e) => executed.Add((e.LastAction.Id, e.PendingExecutionOnDevice, e.PendingExecutionTotal));

        bot.MoveTo(400, 0, 400);
        for (int i = 0; i < 4; i++)
        {
            bot.Move(10, 0, 0);
        }
        Assert.Equal(2, driver.Sent.Count);      // one block of 2; 3 wait to be sent
        await ExecuteAsync(bot, driver, 1);                 // 2 on the device, 3 to 5 waiting: 4 left in all

        Assert.Equal((1, 1, 4), Assert.Single(executed));
    }

    /// <summary>The controller reports <paramref name="id"/> done; returns once its event was raised.</summary>
    private static async Task ExecuteAsync(Robot bot, FakeDriver driver, int id)
    {
        driver.Ack(id);
        await bot.FlushEventsAsync().WaitAsync(Limit);
    }
}
