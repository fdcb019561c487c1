namespace Machina.Tests.Control;

/// <summary>Robot.WaitForRoomAsync: back-pressure for a caller that issues a long program as the robot goes.</summary>
public class WaitForRoomTests
{
    [Fact]
    public async Task WaitForRoom_CompletesOnlyOnceAnExecutionLeavesFewerThanTheMaximumPending()
    {
        var driver = new FakeDriver();
        var bot = OnlineRobot.Create(driver);
        var executed = new List<int>();
        bot.ActionExecuted += (_, e) => executed.Add(e.LastAction.Id);
        bot.MoveTo(400, 0, 400);
        bot.Move(10, 0, 0);
        bot.Move(10, 0, 0);

        Task room = bot.WaitForRoomAsync(3);
        OnlineRobot.Flush(bot);
        Assert.False(room.IsCompleted);   // 3 pending, not fewer than 3

        driver.Ack(1);
        await room.WaitAsync(OnlineRobot.Timeout);
        // The executed event of the action that made room was raised before the wait returned.
        Assert.Equal([1], executed);
        Assert.Equal(2, bot.GetPendingActions().Count);
    }

    [Fact]
    public async Task WaitForRoom_WithRoomAlready_CompletesAtOnce_OfflineToo()
    {
        var bot = OnlineRobot.Create(new FakeDriver());
        bot.MoveTo(400, 0, 400);
        await bot.WaitForRoomAsync(2).WaitAsync(OnlineRobot.Timeout);

        var offline = Robot.Create("Offline", "ABB");
        offline.MoveTo(400, 0, 400);
        for (int i = 0; i < 5; i++)
        {
            offline.Move(10, 0, 0);
        }
        Task atOnce = offline.WaitForRoomAsync(1);
        Assert.True(atOnce.IsCompletedSuccessfully);
    }

    [Fact]
    public async Task WaitForRoom_WhenTheControllerFails_ThrowsTheFailure_AndKeepsThrowingUntilTheNextConnection()
    {
        var driver = new FakeDriver();
        var bot = OnlineRobot.Create(driver);
        bot.MoveTo(400, 0, 400);
        bot.Move(10, 0, 0);
        bot.Move(10, 0, 0);
        Task room = bot.WaitForRoomAsync(2);
        OnlineRobot.Flush(bot);
        Assert.False(room.IsCompleted);

        driver.Listener!.OnFailed(1, "Position outside reach.", "50050");

        var error = await Assert.ThrowsAsync<ActionFailedException>(() => room.WaitAsync(OnlineRobot.Timeout));
        Assert.Equal(1, error.Action.Id);
        Assert.Equal("Position outside reach.", error.ControllerReason);
        Assert.Equal("50050", error.ControllerCode);
        // Nothing is pending any more (the rest was cancelled), but a caller streaming on must not issue into a stopped program.
        var again = await Assert.ThrowsAsync<ActionFailedException>(() => bot.WaitForRoomAsync(100).WaitAsync(OnlineRobot.Timeout));
        Assert.Same(error, again);
    }

    [Fact]
    public async Task WaitForRoom_ConnectionLost_FailsWithTheReason_NotConnected_FailsAtOnceWhenItWouldWait()
    {
        var driver = new FakeDriver();
        var bot = OnlineRobot.Create(driver);
        bot.MoveTo(400, 0, 400);
        bot.Move(10, 0, 0);
        Task room = bot.WaitForRoomAsync(1);
        OnlineRobot.Flush(bot);
        Assert.False(room.IsCompleted);

        driver.Listener!.OnFault(new RobotConnectionException("cable pulled"));

        var lost = await Assert.ThrowsAsync<RobotConnectionException>(() => room.WaitAsync(OnlineRobot.Timeout));
        Assert.Contains("cable pulled", lost.Message, StringComparison.Ordinal);

        var idle = OnlineRobot.Create(new FakeDriver(), connect: false);
        idle.MoveTo(400, 0, 400);
        var notConnected = await Assert.ThrowsAsync<RobotConnectionException>(() => idle.WaitForRoomAsync(1).WaitAsync(OnlineRobot.Timeout));
        Assert.Equal("1 action waits to be executed but the robot is not connected; call Connect first.", notConnected.Message);
        await idle.WaitForRoomAsync(2).WaitAsync(OnlineRobot.Timeout);   // room enough: no connection needed to issue more
    }

    [Fact]
    public async Task WaitForRoom_DisposedWhileWaiting_FailsWithObjectDisposed_BadMaximumRefused()
    {
        var bot = OnlineRobot.Create(new FakeDriver());
        bot.MoveTo(400, 0, 400);
        Task room = bot.WaitForRoomAsync(1);
        OnlineRobot.Flush(bot);

        await bot.DisposeAsync();

        var error = await Assert.ThrowsAsync<ObjectDisposedException>(() => room.WaitAsync(OnlineRobot.Timeout));
        Assert.StartsWith("Cannot wait for room: the robot \"Online\" was disposed.", error.Message, StringComparison.Ordinal);
        var bad = Assert.Throws<ArgumentOutOfRangeException>(() => { _ = Robot.Create("R", "ABB").WaitForRoomAsync(0); });
        Assert.Equal("maxPending", bad.ParamName);
    }
}
