using System.Collections.Concurrent;
using System.Net;
using Machina.Simulation;
using Machina.Simulation.Rapid;
using Machina.Tests.Online;
using Machina.Tests.Support;

namespace Machina.Tests.Simulation.Rapid;

/// <summary>
/// Machina's own RAPID driver and monitor (drivers/abb, filled by AbbDriverModules) run unchanged on the RAPID twin, each in its task
/// (T_ROB1 and T_MACHINA_MONITOR), and the library's online ABB robot streams to them over loopback as to an IRC5.
/// </summary>
public sealed class RapidDriverTwinTests : IDisposable
{
    private const string Monitor = "T_MACHINA_MONITOR";
    private readonly RapidTwinController _twin;
    private readonly int _port;

    public RapidDriverTwinTests()
    {
        (System.Net.Sockets.TcpListener driver, System.Net.Sockets.TcpListener monitor) = LoopbackPorts.BindPair();
        _port = ((IPEndPoint)driver.LocalEndpoint).Port;
        _twin = new RapidTwinController(new RapidTwinOptions { Model = RobotModels.Get("IRB 1600-8/1.45") });
        foreach ((string file, string text) in AbbDriverModules.Create("127.0.0.1", _port).Where(m => m.Key.EndsWith(".mod", StringComparison.Ordinal)))
        {
            _twin.Task(file.Contains("monitor", StringComparison.Ordinal) ? Monitor : RapidTwinController.MotionTask).Load([(file, text)]);
        }
        _twin.Reserve(driver);
        _twin.Reserve(monitor);
        _twin.StartTasks();
    }

    public void Dispose() => Assert.True(_twin.StopTasks(TimeSpan.FromSeconds(10)), "the RAPID tasks to stop");

    [Fact]
    public async Task HelloRobot_StreamsToTheInterpretedDriver_SevenOfSevenExecutedInOrder()
    {
        var executed = new ConcurrentQueue<ActionExecutedArgs>();
        Robot bot = await OnlineTestSupport.ConnectRobotAsync("HelloRobot", "ABB", _port, b => b.ActionExecuted += (_, e) => executed.Enqueue(e));
        try
        {
            ReferencePrograms.HelloRobot(bot);
            await bot.WaitForCompletionAsync().WaitAsync(OnlineTestSupport.Limit);

            ActionExecutedArgs[] seen = [.. executed];
            Assert.Equal([1, 2, 3, 4, 5, 6, 7], seen.Select(e => e.LastAction.Id));
            Assert.Equal(new Vector(400, 300, 750), seen[4].Position);
            Assert.Contains("Hello Robot!", _twin.Pendant.Lines);
            Assert.Equal(RapidProgramState.Running, _twin.Task().State);
            Joints joints = _twin.Arm.Joints;
            Assert.Equal(new[] { 0.0, 0, 0, 0, 90, 0 }, new[] { joints.J1, joints.J2, joints.J3, joints.J4, joints.J5, joints.J6 }.Select(j => Math.Round(j, 6)));
            // The twin moved for the three MoveL and the MoveAbsJ, and waited 2 s (program time): what the driver ran, once each.
            Assert.Equal(["MoveL", "MoveL", "MoveL", "MoveAbsJ"], _twin.Arm.Trace.Where(t => t.Kind == Machina.Simulation.Twin.TwinTraceKind.Motion).Select(t => t.Text));
        }
        finally
        {
            await bot.DisconnectAsync();
        }
    }

    [Fact]
    public async Task TenThousandActions_ExecutedExactlyOnceInOrder_MonitorReportsLivePoses()
    {
        const int count = 10_000;
        var executed = new ConcurrentQueue<int>();
        var updates = new ConcurrentQueue<MotionUpdateArgs>();
        Robot bot = await OnlineTestSupport.ConnectRobotAsync("Stream", "ABB", _port, b =>
        {
            b.ActionExecuted += (_, e) => executed.Enqueue(e.LastAction.Id);
            b.MotionUpdate += (_, e) => updates.Enqueue(e);
        });
        try
        {
            bot.SpeedTo(500);
            for (int i = 1; i < count; i++)
            {
                bot.MoveTo(600 + i % 2 * 10, i % 7, 600);
            }
            await bot.WaitForCompletionAsync().WaitAsync(TimeSpan.FromMinutes(3));

            Assert.Equal(Enumerable.Range(1, count), executed);
            Assert.Equal(count - 1, _twin.Arm.Trace.Count(t => t.Text == "MoveL"));
            Pose tcp = _twin.Arm.Tcp;
            Assert.True(tcp.Position.IsSimilar(new Vector(610, 9_999 % 7, 600), 1e-3), tcp.Position.ToString());
            await OnlineTestSupport.EventuallyAsync(
                () => updates.LastOrDefault() is { Position: Vector p } && p.IsSimilar(tcp.Position, 1e-3), "the monitor to report the last pose");
        }
        finally
        {
            await bot.DisconnectAsync();
        }
    }

    [Fact]
    public async Task UnreachableMoveL_MonitorTrapReportsEvent50050_HostReportsTheActionFailed()
    {
        var failed = new TaskCompletionSource<ActionFailedArgs>(TaskCreationOptions.RunContinuationsAsynchronously);
        var executed = new ConcurrentQueue<int>();
        Robot bot = await OnlineTestSupport.ConnectRobotAsync("Reach", "ABB", _port, b =>
        {
            b.ActionExecuted += (_, e) => executed.Enqueue(e.LastAction.Id);
            b.ActionFailed += (_, e) => failed.TrySetResult(e);
        });
        try
        {
            bot.SpeedTo(100);
            bot.MoveTo(600, 0, 600);
            Assert.True(bot.WaitForCompletion(OnlineTestSupport.Limit));
            bot.Do("MoveTo(5000, 0, 600); MoveTo(600, 0, 500);");
            ActionFailedArgs e = await failed.Task.WaitAsync(OnlineTestSupport.Limit);

            Assert.Equal(3, e.Action.Id);
            Assert.Equal("50050", e.Failure.ControllerCode);
            Assert.Equal([4], e.CancelledActions.Select(a => a.Id));
            Assert.Equal([1, 2], executed);
            Assert.Equal(RapidProgramState.Failed, _twin.Task().State);
            Assert.StartsWith("50050 Position outside reach", _twin.Task().Error, StringComparison.Ordinal);
            Assert.True(_twin.Arm.Tcp.Position.IsSimilar(new Vector(600, 0, 600), 1e-3), _twin.Arm.Tcp.Position.ToString());
        }
        finally
        {
            await bot.DisconnectAsync();
        }
    }
}
