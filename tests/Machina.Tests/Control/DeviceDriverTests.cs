using System.Collections.Concurrent;
using System.Net;
using System.Net.Sockets;
using System.Text;
using Machina.Tests.Support;

namespace Machina.Tests.Control;

/// <summary>
/// The lifecycle every driver shares (<see cref="DeviceDriver{TMessage}"/>), through the smallest brand on it
/// (<see cref="LineDriver"/>): the handshake, the receive loop, failing exactly once, the monitor link and disposal.
/// </summary>
public class DeviceDriverTests
{
    private static readonly TimeSpan Limit = TimeSpan.FromSeconds(15);

    [Fact]
    public async Task Fail_ManyThreadsCloseAndSendGarbageAtOnce_ListenerHearsExactlyOneFault()
    {
        string[] expected =
        [
            "The test controller closed the connection.",
            "The connection to the test controller failed: reset",
            "Garbage from the test controller: bad!",
        ];
        for (int round = 0; round < 50; round++)
        {
            var (driver, listener) = await ConnectedAsync();
            using var start = new Barrier(6);
            Task[] faults = [.. Enumerable.Range(0, 6).Select(i => Task.Run(() =>
            {
                start.SignalAndWait(Limit);
                // One thread receives, as a link's one receive loop does; the others close it at the same time.
                switch (i)
                {
                    case 2: driver.Receive("bad!\n"); break;
                    case 0 or 3 or 5: driver.OnClosed(null); break;
                    default: driver.OnClosed(new IOException("reset")); break;
                }
            }))];
            await Task.WhenAll(faults).WaitAsync(Limit);

            MachinaException fault = Assert.Single(listener.Faults);
            Assert.Contains(fault.Message, expected);
            driver.OnClosed(null);
            driver.Receive("ack 7\n");
            Assert.Single(listener.Faults);
            Assert.Empty(listener.Acknowledged);
            await driver.DisposeAsync();
        }
    }

    [Fact]
    public async Task Fail_BeforeTheHandshake_ConnectThrowsItAndTheListenerHearsNothing()
    {
        var listener = new RecordingListener();
        var driver = new LineDriver(new RobotLogger("test"), TimeProvider.System);
        Task<DeviceHandshake> connect = driver.ConnectAsync("127.0.0.1", 1, listener, Limit, CancellationToken.None);

        driver.OnClosed(null);
        var error = await Assert.ThrowsAsync<RobotConnectionException>(() => connect.WaitAsync(Limit));
        Assert.Equal("The test controller closed the connection.", error.Message);
        driver.Receive("hello 1.0\nack 1\n");
        Assert.Empty(listener.Faults);
        Assert.Empty(listener.Acknowledged);
        Assert.Empty(driver.Handled);
        await driver.DisposeAsync();
    }

    [Fact]
    public async Task Handshake_ControllerSilent_FailsWithTheBrandsSentenceWhenTheTimeoutPasses()
    {
        var clock = new ManualClock();
        var driver = new LineDriver(new RobotLogger("test"), clock);
        Task<DeviceHandshake> connect = driver.ConnectAsync("127.0.0.1", 1, new RecordingListener(), TimeSpan.FromSeconds(5), CancellationToken.None);

        await Eventually.TrueAsync(() => clock.HasTimerDueIn(TimeSpan.FromSeconds(5)), "the handshake to wait", Limit);
        clock.Advance(TimeSpan.FromSeconds(4.9));
        Assert.False(connect.IsCompleted);
        clock.Advance(TimeSpan.FromSeconds(0.1));
        var error = await Assert.ThrowsAsync<RobotConnectionException>(() => connect.WaitAsync(Limit));
        Assert.Equal(LineDriver.Silence, error.Message);
        await driver.DisposeAsync();
    }

    [Fact]
    public async Task OnReceived_GarbageBetweenMessages_HandlesWhatCameBeforeAndNothingAfter()
    {
        var (driver, listener) = await ConnectedAsync();

        driver.Receive("ack 1\nack 2\nbad!\nack 3\n");
        driver.Receive("ack 4\n");

        Assert.Equal([1, 2], listener.Acknowledged);
        Assert.Equal(["hello 2.1", "ack 1", "ack 2"], driver.Handled);
        var fault = Assert.IsType<RobotConnectionException>(Assert.Single(listener.Faults));
        Assert.Equal("Garbage from the test controller: bad!", fault.Message);
        Assert.Equal("bad!", fault.ReceivedText);
        await driver.DisposeAsync();
    }

    [Fact]
    public async Task OnReceived_MessagesSplitAnywhere_ReadWhole()
    {
        var (driver, listener) = await ConnectedAsync();

        foreach (char c in "ack 12\nac")
        {
            driver.Receive(c.ToString());
        }
        driver.Receive("k 345\n");

        Assert.Equal([12, 345], listener.Acknowledged);
        Assert.Empty(listener.Faults);
        await driver.DisposeAsync();
    }

    [Fact]
    public async Task OnClosed_SocketError_NamesThePeerAndKeepsTheCause()
    {
        var (driver, listener) = await ConnectedAsync();
        var cause = new IOException("Connection reset by peer");

        driver.OnClosed(cause);

        var fault = Assert.IsType<RobotConnectionException>(Assert.Single(listener.Faults));
        Assert.Equal("The connection to the test controller failed: Connection reset by peer", fault.Message);
        Assert.Same(cause, fault.InnerException);
        await driver.DisposeAsync();
    }

    [Fact]
    public async Task DisposeAsync_ThenTheLinkCloses_NoFaultIsReported()
    {
        var (driver, listener) = await ConnectedAsync();

        await driver.DisposeAsync();
        driver.OnClosed(null);
        driver.Receive("ack 1\n");

        Assert.Empty(listener.Faults);
        Assert.Empty(listener.Acknowledged);
    }

    [Fact]
    public async Task Monitor_PosesThenGarbage_ReportsThePosesThenWarnsOnceAndNeverFaults()
    {
        using var server = new TcpListener(IPAddress.Loopback, 0);
        server.Start();
        var log = new RobotLogger("test");
        var warnings = new ConcurrentQueue<string>();
        using var sink = log.AddSink(e => warnings.Enqueue(e.Message), LogLevel.WARNING);
        var listener = new RecordingListener();
        var driver = new LineDriver(log, TimeProvider.System, "127.0.0.1", ((IPEndPoint)server.LocalEndpoint).Port);
        Task<DeviceHandshake> connect = driver.ConnectAsync("127.0.0.1", 1, listener, Limit, CancellationToken.None);
        driver.Receive("hello 2.1\n");
        using Socket monitor = await server.AcceptSocketAsync().WaitAsync(Limit);
        await connect.WaitAsync(Limit);
        Assert.True(driver.HasMonitor);

        await monitor.SendAsync(Encoding.ASCII.GetBytes("pose 10\npose 20.5\nhello 3\npose 30\n"));
        await Eventually.TrueAsync(() => !warnings.IsEmpty, "the monitor to stop", Limit);
        await monitor.SendAsync(Encoding.ASCII.GetBytes("pose 40\n"));
        monitor.Shutdown(SocketShutdown.Both);

        Assert.Equal([10, 20.5], listener.Motion.Select(m => m.Position.X));
        Assert.Equal(["Motion updates stopped: it sent hello 3."], warnings);
        Assert.Empty(listener.Faults);
        await driver.DisposeAsync();
        Assert.Equal(["Motion updates stopped: it sent hello 3."], warnings);
    }

    [Fact]
    public async Task Monitor_NoneOnThatPort_LogsAndConnectsWithoutIt()
    {
        using var closed = new TcpListener(IPAddress.Loopback, 0);
        closed.Start();
        int port = ((IPEndPoint)closed.LocalEndpoint).Port;
        closed.Stop(); // nothing listens there any more: the connection is refused
        var log = new RobotLogger("test");
        var infos = new ConcurrentQueue<string>();
        using var sink = log.AddSink(e => infos.Enqueue(e.Message), LogLevel.INFO);
        var driver = new LineDriver(log, TimeProvider.System, "127.0.0.1", port);

        Task<DeviceHandshake> connect = driver.ConnectAsync("127.0.0.1", 1, new RecordingListener(), Limit, CancellationToken.None);
        driver.Receive("hello 2.1\n");
        DeviceHandshake handshake = await connect.WaitAsync(Limit);

        Assert.Equal("2.1", handshake.Version);
        Assert.False(driver.HasMonitor);
        Assert.Equal(["No monitor here."], infos);
        await driver.DisposeAsync();
    }

    private static async Task<(LineDriver Driver, RecordingListener Listener)> ConnectedAsync()
    {
        var listener = new RecordingListener();
        var driver = new LineDriver(new RobotLogger("test"), TimeProvider.System);
        Task<DeviceHandshake> connect = driver.ConnectAsync("127.0.0.1", 1, listener, Limit, CancellationToken.None);
        driver.Receive("hello 2.1\n");
        Assert.Equal("2.1", (await connect.WaitAsync(Limit)).Version);
        return (driver, listener);
    }
}
