namespace Machina.Tests.Control;

/// <summary>
/// <see cref="Robot.DisconnectAsync(CancellationToken)"/>: the wait for the driver's links to close can be cancelled; the robot
/// ends disconnected all the same, and the close goes on by itself.
/// </summary>
public sealed class DisconnectCancellationTests
{
    private static readonly TimeSpan Bound = TimeSpan.FromSeconds(20);

    [Fact]
    public async Task DisconnectAsync_WhoseDriverNeverFinishesClosing_EndsWhenCancelled_AndTheRobotIsDisconnected()
    {
        var driver = new ClosingDriver();
        Robot bot = await ConnectedAsync(driver);
        using var cancel = new CancellationTokenSource();

        Task disconnecting = bot.DisconnectAsync(cancel.Token);
        await driver.Closing.Task.WaitAsync(Bound);   // the driver is being disposed, and its dispose does not end
        Assert.False(disconnecting.IsCompleted);
        await cancel.CancelAsync();

        await Assert.ThrowsAnyAsync<OperationCanceledException>(() => disconnecting.WaitAsync(Bound));
        Assert.False(bot.IsConnected);
        Assert.Equal(ConnectionState.Disconnected, bot.ConnectionState);
        driver.Closed.SetResult();   // the abandoned close ends by itself
    }

    [Fact]
    public async Task DisconnectAsync_WithATokenNotCancelled_WaitsForTheDriversClose()
    {
        var driver = new ClosingDriver();
        Robot bot = await ConnectedAsync(driver);
        using var cancel = new CancellationTokenSource();

        Task disconnecting = bot.DisconnectAsync(cancel.Token);
        await driver.Closing.Task.WaitAsync(Bound);
        Assert.False(disconnecting.IsCompleted);
        driver.Closed.SetResult();

        await disconnecting.WaitAsync(Bound);
        Assert.True(disconnecting.IsCompletedSuccessfully);
        Assert.Equal(ConnectionState.Disconnected, bot.ConnectionState);
    }

    [Fact]
    public async Task DisconnectAsync_WithATokenAlreadyCancelled_StillDisconnects()
    {
        var driver = new ClosingDriver();
        driver.Closed.SetResult();
        Robot bot = await ConnectedAsync(driver);

        // The driver closes at once here, so the disconnection completes before the cancelled wait is looked at.
        await bot.DisconnectAsync(new CancellationToken(canceled: true)).WaitAsync(Bound);

        Assert.True(driver.Closing.Task.IsCompleted);
        Assert.Equal(ConnectionState.Disconnected, bot.ConnectionState);
    }

    /// <summary>An ABB robot online and connected through <paramref name="driver"/>.</summary>
    private static async Task<Robot> ConnectedAsync(ClosingDriver driver)
    {
        var bot = Robot.Create("Closing", "ABB");
        bot.DriverFactory = () => driver;
        bot.ControlMode("online");
        await bot.ConnectAsync("127.0.0.1", 7000).WaitAsync(Bound);
        return bot;
    }

    /// <summary>A driver without a network whose dispose waits until the test lets it end (a link thread that does not end).</summary>
    private sealed class ClosingDriver : IDeviceDriver
    {
        /// <summary>Set when the session starts disposing the driver.</summary>
        internal TaskCompletionSource Closing { get; } = new(TaskCreationOptions.RunContinuationsAsynchronously);

        /// <summary>Set by the test to let the dispose end.</summary>
        internal TaskCompletionSource Closed { get; } = new(TaskCreationOptions.RunContinuationsAsynchronously);

        public string RemoteAddress => "closing:1";

        public Task<DeviceHandshake> ConnectAsync(string host, int port, IDeviceListener listener, TimeSpan timeout, CancellationToken cancellationToken) =>
            Task.FromResult(new DeviceHandshake("1.5.0", new Vector(300, 0, 500), Rotation.FlippedAroundY, new Joints(0, 0, 0, 0, 90, 0), null));

        public bool Send(RobotAction action, ActionFrame frame) => true;

        public int WireId(int actionId) => actionId;

        public void Adopt(int actionId)
        {
        }

        public async ValueTask DisposeAsync()
        {
            Closing.TrySetResult();
            await Closed.Task;
        }
    }
}
