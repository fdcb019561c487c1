namespace Machina.Tests.Control;

/// <summary>A disposed robot refuses everything, always, even when it is disposed while connecting or waiting.</summary>
public class DisposalTests
{
    [Fact]
    public async Task DisposeAsync_DuringConnect_ConnectFails_RobotStaysDisconnectedAndRefusesEverything()
    {
        using var entered = new ManualResetEventSlim();
        using var release = new ManualResetEventSlim();
        var driver = new FakeDriver
        {
            DuringConnect = _ =>
            {
                entered.Set();
                release.Wait(OnlineRobot.Timeout);   // the handshake is under way while the robot is disposed
            },
        };
        var bot = OnlineRobot.Create(driver, connect: false);
        Task connecting = Task.Run(() => bot.ConnectAsync("127.0.0.1", 7000));
        Assert.True(entered.Wait(OnlineRobot.Timeout));

        await bot.DisposeAsync().AsTask().WaitAsync(OnlineRobot.Timeout);
        release.Set();

        var connectError = await Assert.ThrowsAsync<ObjectDisposedException>(() => connecting.WaitAsync(OnlineRobot.Timeout));
        Assert.StartsWith("Cannot connect: the robot \"Online\" was disposed. Create a new robot.", connectError.Message);
        Assert.Equal(ConnectionState.Disconnected, bot.ConnectionState);
        Assert.False(bot.IsConnected);
        Assert.True(driver.Disposed);

        var moveError = Assert.Throws<ObjectDisposedException>(() => bot.MoveTo(400, 0, 400));
        Assert.StartsWith("Cannot issue MoveTo(400,0,400): the robot \"Online\" was disposed. Create a new robot.", moveError.Message);
        var waitError = await Assert.ThrowsAsync<ObjectDisposedException>(() => bot.WaitForCompletionAsync());
        Assert.StartsWith("Cannot wait for completion: the robot \"Online\" was disposed.", waitError.Message);
        Assert.Throws<ObjectDisposedException>(() => bot.Connect("127.0.0.1", 7000));
        await Assert.ThrowsAsync<ObjectDisposedException>(() => bot.ResumeAsync());
        Assert.Throws<ObjectDisposedException>(() => bot.ControlMode("offline"));
        Assert.Empty(driver.Sent);
        Assert.Empty(bot.GetPendingActions());
    }

    [Fact]
    public async Task DisposeAsync_WhileWaitingForCompletion_TheWaitFailsWithObjectDisposed()
    {
        var driver = new FakeDriver();
        var bot = OnlineRobot.Create(driver);
        bot.MoveTo(400, 0, 400);
        Task waiting = bot.WaitForCompletionAsync();

        await bot.DisposeAsync();

        var error = await Assert.ThrowsAsync<ObjectDisposedException>(() => waiting.WaitAsync(OnlineRobot.Timeout));
        Assert.StartsWith("Cannot wait for completion: the robot \"Online\" was disposed. Create a new robot.", error.Message);
        Assert.True(driver.Disposed);
        Assert.Equal(ConnectionState.Disconnected, bot.ConnectionState);
    }

    [Fact]
    public void Dispose_OfflineRobot_VerbsRefused_NothingRecorded()
    {
        var bot = Robot.Create("Offline", "ABB");
        bot.MoveTo(400, 0, 400);
        bot.Dispose();

        var error = Assert.Throws<ObjectDisposedException>(() => bot.Move(10, 0, 0));
        Assert.StartsWith("Cannot issue Move(10,0,0): the robot \"Offline\" was disposed. Create a new robot.", error.Message);
        Assert.Throws<ObjectDisposedException>(() => bot.ControlMode("online"));
        Assert.Equal([1], bot.GetProgramActions().Select(a => a.Id));
        bot.Dispose();   // twice is fine
    }
}
