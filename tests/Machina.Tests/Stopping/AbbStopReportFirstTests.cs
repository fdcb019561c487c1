using System.Collections.Concurrent;
using System.Net;
using System.Net.Sockets;
using System.Text;
using Machina.Simulation;
using Machina.Tests.Online;

namespace Machina.Tests.Stopping;

/// <summary>
/// Robot.Stop on ABB when the driver task's report of the stopped move (<c>$26 id 4;</c>, from its interrupt on
/// machinaStopRequest) reaches the host before the monitor task's answer to "S" (<c>$28 3;</c>): the monitor sets the request
/// and then answers, so a loaded controller may let the driver's task run first. The host applies the report as the stop and
/// closes the link, so the answer is never read. A scripted controller plays that order without timing: it answers "S" only
/// once the host has closed the driver link. Before session 36 Robot.Stop then waited for the answer until its 10 s limit and
/// threw "did not answer the stop command", although the robot had stopped and ActionFailed had been raised.
/// </summary>
public class AbbStopReportFirstTests
{
    private static readonly TimeSpan Long = TimeSpan.FromSeconds(60);

    [Fact]
    public async Task Stop_DriverReportsTheStoppedMoveBeforeTheMonitorAnswers_StopReturnsAndTheMoveFailsStopped()
    {
        (TcpListener driverListener, TcpListener monitorListener) = LoopbackPorts.BindPair();
        try
        {
            int port = ((IPEndPoint)driverListener.LocalEndpoint).Port;
            var failed = new TaskCompletionSource<ActionFailedArgs>(TaskCreationOptions.RunContinuationsAsynchronously);
            var executed = new ConcurrentQueue<int>();
            Task<Robot> connecting = OnlineTestSupport.ConnectRobotAsync("HelloRobot", "ABB", port, b =>
            {
                b.ActionFailed += (_, e) => failed.TrySetResult(e);
                b.ActionExecuted += (_, e) => executed.Enqueue(e.LastAction.Id);
            });
            using TcpClient driver = await driverListener.AcceptTcpClientAsync().WaitAsync(Long);
            NetworkStream d = driver.GetStream();
            await WriteAsync(d, "$20 1 7 0;$21 300 0 500 0 0 1 0;$22 0 0 0 0 90 0;$23 9E9 9E9 9E9 9E9 9E9 9E9;$25 0 0;");
            using TcpClient monitor = await monitorListener.AcceptTcpClientAsync().WaitAsync(Long);
            NetworkStream m = monitor.GetStream();
            Assert.Equal("M", await ReadAsync(m));
            await WriteAsync(m, "$@0 101 3 IRB 120-3/0.6;");
            Robot bot = await connecting.WaitAsync(Long);
            try
            {
                bot.Do("SpeedTo(10); Move(0, 0, -200); WriteDigital(\"DO_2\", true);");
                var sent = new StringBuilder();
                while (!sent.ToString().Contains("@3 10 ", StringComparison.Ordinal))
                {
                    sent.Append(await ReadAsync(d));
                }
                Assert.Matches(@"^@1 4 [^;]*;@2 1 [^;]*;@3 10 ", sent.ToString());
                await WriteAsync(d, "@1 4;"); // the speed is set; the move runs

                Task stopping = bot.StopAsync();
                Assert.Equal("S", await ReadAsync(m));
                // The driver's task reports the move it failed on the host's stop before the monitor answers...
                await WriteAsync(d, "$26 2 4;");
                // ...and the host, applying it, closes the link: only then does the monitor's answer go out (never read).
                Assert.Equal("", await ReadAsync(d));
                try
                {
                    await WriteAsync(m, "$28 3;");
                }
                catch (IOException)
                {
                    // The host closed the monitor link first.
                }

                await stopping.WaitAsync(Long); // threw "did not answer the stop command within 10 s" before
                ActionFailedArgs e = await failed.Task.WaitAsync(Long);
                Assert.Equal(2, e.Action.Id);
                Assert.Equal("stopped by the user (Robot.Stop): the motion stopped where the arm was and nothing after it ran.", e.Reason);
                Assert.Equal("stopped", e.Failure.ControllerCode);
                Assert.Equal([3], e.CancelledActions.Select(a => a.Id));
                Assert.False(bot.IsConnected);
                await bot.FlushEventsAsync();
                Assert.Equal([1], executed);
            }
            finally
            {
                await bot.DisconnectAsync();
            }
        }
        finally
        {
            driverListener.Stop();
            monitorListener.Stop();
        }
    }

    private static async Task WriteAsync(NetworkStream stream, string text) =>
        await stream.WriteAsync(Encoding.ASCII.GetBytes(text)).AsTask().WaitAsync(Long);

    /// <summary>What the host wrote next ("" once it closed the connection).</summary>
    private static async Task<string> ReadAsync(NetworkStream stream)
    {
        byte[] buffer = new byte[4096];
        int count = await stream.ReadAsync(buffer).AsTask().WaitAsync(Long);
        return Encoding.ASCII.GetString(buffer, 0, count);
    }
}
