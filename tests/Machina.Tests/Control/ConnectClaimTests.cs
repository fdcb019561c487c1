using System.Collections.Concurrent;

namespace Machina.Tests.Control;

/// <summary>
/// Connecting claims the connection on the caller's thread and makes one trip into the session's loop, to attach it: while a
/// handshake runs the robot reads Connecting and refuses a second connect; a failed handshake drops its claim and its reports.
/// </summary>
public class ConnectClaimTests
{
    [Fact]
    public async Task ConnectAsync_WhileAHandshakeRuns_ReadsConnectingAndRefusesASecondConnect()
    {
        using var entered = new ManualResetEventSlim();
        using var release = new ManualResetEventSlim();
        int made = 0;
        var driver = new FakeDriver
        {
            DuringConnect = _ =>
            {
                entered.Set();
                release.Wait(OnlineRobot.Timeout);
            },
        };
        var bot = Robot.Create("Online", "ABB");
        bot.DriverFactory = () =>
        {
            Interlocked.Increment(ref made);
            return driver;
        };
        bot.ControlMode("online");
        Task connecting = Task.Run(() => bot.ConnectAsync("127.0.0.1", 7000));
        Assert.True(entered.Wait(OnlineRobot.Timeout));

        Assert.Equal(ConnectionState.Connecting, bot.ConnectionState);
        Assert.False(bot.IsConnected);
        var second = await Assert.ThrowsAsync<InvalidOperationException>(() => bot.ConnectAsync("127.0.0.1", 7000));
        Assert.Equal("The robot is already connecting; call Disconnect first.", second.Message);

        release.Set();
        await connecting.WaitAsync(OnlineRobot.Timeout);
        Assert.Equal(ConnectionState.Connected, bot.ConnectionState);
        var third = Assert.Throws<InvalidOperationException>(() => bot.Connect("127.0.0.1", 7000));
        Assert.Equal("The robot is already connected; call Disconnect first.", third.Message);
        Assert.Equal(1, made);   // a refused connect makes no driver
        Assert.False(driver.Disposed);
    }

    [Fact]
    public async Task ConnectAsync_HandshakeFailsAfterReporting_ItsReportsAreDroppedAndTheNextConnectAttaches()
    {
        var failing = new FakeDriver
        {
            DuringConnect = listener =>
            {
                // Held while connecting; the link never becomes current, so they must never reach the next one.
                listener.OnFault(new RobotConnectionException("the old link broke"));
                listener.OnAcknowledged(1);
                throw new RobotConnectionException("Could not connect: the handshake was cut.");
            },
        };
        var working = new FakeDriver(autoAcknowledge: true);
        var drivers = new Queue<FakeDriver>([failing, working]);
        var bot = Robot.Create("Online", "ABB");
        bot.DriverFactory = drivers.Dequeue;
        bot.ControlMode("online");
        bot.MoveTo(400, 0, 400);

        var error = await Assert.ThrowsAsync<RobotConnectionException>(() => bot.ConnectAsync("127.0.0.1", 7000));
        Assert.Equal("Could not connect: the handshake was cut.", error.Message);
        Assert.Equal(ConnectionState.Disconnected, bot.ConnectionState);
        Assert.True(failing.Disposed);

        await bot.ConnectAsync("127.0.0.1", 7000).WaitAsync(OnlineRobot.Timeout);
        await bot.WaitForCompletionAsync().WaitAsync(OnlineRobot.Timeout);
        Assert.Equal(ConnectionState.Connected, bot.ConnectionState);
        Assert.Equal([1], working.Sent.Select(a => a.Id));
        Assert.Empty(failing.Sent);
    }

    [Fact]
    public async Task ConnectAsync_ManyCallersAtOnce_ExactlyOneConnectsAndTheOthersAreRefused()
    {
        using var release = new ManualResetEventSlim();
        var made = new ConcurrentQueue<FakeDriver>();
        var bot = Robot.Create("Online", "ABB");
        bot.DriverFactory = () =>
        {
            var driver = new FakeDriver { DuringConnect = _ => release.Wait(OnlineRobot.Timeout) };
            made.Enqueue(driver);
            return driver;
        };
        bot.ControlMode("online");
        using var start = new ManualResetEventSlim();
        Task[] callers = [.. Enumerable.Range(0, 8).Select(_ => Task.Run(async () =>
        {
            start.Wait(OnlineRobot.Timeout);
            await bot.ConnectAsync("127.0.0.1", 7000);
        }))];
        start.Set();
        // Every refused caller ends before the handshake is let go: refusals never wait for the one that connects.
        for (int i = 0; i < 1000 && callers.Count(c => c.IsCompleted) < callers.Length - 1; i++)
        {
            await Task.Delay(10);
        }
        release.Set();
        await Task.WhenAll(callers.Select(c => c.ContinueWith(_ => { }, TaskScheduler.Default))).WaitAsync(OnlineRobot.Timeout);

        Assert.Equal(1, callers.Count(c => c.IsCompletedSuccessfully));
        Assert.All(callers.Where(c => !c.IsCompletedSuccessfully), c => Assert.IsType<InvalidOperationException>(c.Exception!.InnerException));
        Assert.Equal(ConnectionState.Connected, bot.ConnectionState);
        // A caller that lost the race after making its driver disposed it; the winner's stays open.
        Assert.Equal(1, made.Count(d => !d.Disposed));
    }
}
