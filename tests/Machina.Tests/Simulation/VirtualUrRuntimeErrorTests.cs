using System.Buffers.Binary;
using System.Collections.Concurrent;
using System.Net;
using System.Net.Sockets;
using System.Text;
using Machina.Tests.Online;
using Machina.Simulation;
using Machina.Tests.Support;

namespace Machina.Tests.Simulation;

/// <summary>
/// "Executed" means the robot got there (issue 21 §1, UR): an instruction the virtual UR cannot run stops its program with a
/// runtime error, as a UR does. Nothing after it runs, it is never acknowledged, and the host hears why.
/// </summary>
public class VirtualUrRuntimeErrorTests
{
    private static readonly TimeSpan Timeout = TimeSpan.FromSeconds(15);

    [Fact]
    public async Task UnreachableMoveMidProgram_ProgramStopsWithTheReason_NothingAfterItRuns_NeverAcknowledged()
    {
        await using var controller = new VirtualUrController(new VirtualUrControllerOptions { InstantExecution = true });
        await controller.StartAsync();
        var server = new TcpListener(IPAddress.Loopback, 0);
        server.Start();
        using var script = new TcpClient();
        await script.ConnectAsync(IPAddress.Loopback, controller.Port);
        await script.GetStream().WriteAsync(Encoding.ASCII.GetBytes(UrDriverScript.For("127.0.0.1", ((IPEndPoint)server.LocalEndpoint).Port, 5)));
        using var driver = await server.AcceptTcpClientAsync().WaitAsync(Timeout);
        var stream = driver.GetStream();
        await WireInts.ReadAsync(stream, 19, Timeout);
        VirtualUrState start = controller.State;
        RotationVector rv = start.Rotation.ToRotationVector();
        int[] Move(int id, Vector p) =>
            [id, 1, UrWire.Millimetres(p.X), UrWire.Millimetres(p.Y), UrWire.Millimetres(p.Z), UrWire.Degrees(rv.X), UrWire.Degrees(rv.Y), UrWire.Degrees(rv.Z)];
        Vector reachable = start.Position + new Vector(0, 0, -20);

        await WireInts.WriteAsync(stream, [.. new[] { 1, 15, 100_000 }, .. Move(2, reachable), .. Move(3, new Vector(2000, 0, 500)), .. Move(4, start.Position)]);

        Assert.Equal(new[] { 1, 2 }, await WireInts.ReadAsync(stream, 2, Timeout));
        Assert.Equal(0, await stream.ReadAsync(new byte[4]).AsTask().WaitAsync(Timeout)); // closed: 3 is never acknowledged
        Assert.Equal(new[] { 1, 2 }, controller.ExecutedIds);
        Assert.Equal(1u, controller.RuntimeState); // RTDE runtime_state: stopped
        Assert.False(controller.IsProgramRunning);
        Assert.True(controller.State.Position.IsSimilar(reachable, 0.05), controller.State.Position.ToString());
        string error = controller.LastRuntimeException!;
        Assert.Equal("movel: no inverse kinematics solution: the target pose is out of reach", error);

        // The script port (a client interface) carried the runtime exception: robot message 20, runtime exception 10, the text.
        byte[] package = await ReadPackageAsync(script.GetStream());
        Assert.Equal((20, 10), (package[4], package[14]));
        int line = BinaryPrimitives.ReadInt32BigEndian(package.AsSpan(15));
        Assert.Contains("movel(", UrDriverScript.For("127.0.0.1", 1, 5).Split('\n')[line - 1], StringComparison.Ordinal);
        Assert.Equal(error, Encoding.ASCII.GetString(package, 23, package.Length - 23));
        server.Stop();
    }

    [Fact]
    public async Task ZeroSpeedOnTheWire_NextMoveStopsTheProgram()
    {
        // Issuing refuses a speed that rounds to 0; a host that sends one anyway meets a UR that cannot move at it.
        await using var controller = new VirtualUrController(new VirtualUrControllerOptions { InstantExecution = true });
        await controller.StartAsync();
        var server = new TcpListener(IPAddress.Loopback, 0);
        server.Start();
        using var script = new TcpClient();
        await script.ConnectAsync(IPAddress.Loopback, controller.Port);
        await script.GetStream().WriteAsync(Encoding.ASCII.GetBytes(UrDriverScript.For("127.0.0.1", ((IPEndPoint)server.LocalEndpoint).Port, 6)));
        using var driver = await server.AcceptTcpClientAsync().WaitAsync(Timeout);
        var stream = driver.GetStream();
        await WireInts.ReadAsync(stream, 19, Timeout);

        await WireInts.WriteAsync(stream, [1, 15, 0, 2, 3, 0, -15708, -15708, -15708, 15708, 1000]);

        Assert.Equal(new[] { 1 }, await WireInts.ReadAsync(stream, 1, Timeout));
        Assert.Equal(0, await stream.ReadAsync(new byte[4]).AsTask().WaitAsync(Timeout));
        Assert.Equal(new[] { 1 }, controller.ExecutedIds);
        Assert.Equal("movej: speed 'v' and acceleration 'a' must be positive", controller.LastRuntimeException);
        server.Stop();
    }

    [Fact]
    public async Task Robot_UnreachableMove_ReportedFailedWithTheControllerReason_LaterActionsNeverRun()
    {
        await using var controller = new VirtualUrController(new VirtualUrControllerOptions { InstantExecution = true });
        await controller.StartAsync();
        var failed = new TaskCompletionSource<ActionFailedArgs>(TaskCreationOptions.RunContinuationsAsynchronously);
        var executed = new ConcurrentQueue<int>();
        Robot bot = await UrOnlineTestSupport.ConnectUrAsync(controller, b =>
        {
            b.ActionExecuted += (_, e) => executed.Enqueue(e.LastAction.Id);
            b.ActionFailed += (_, e) => failed.TrySetResult(e);
        });
        try
        {
            Vector at = controller.State.Position;
            bot.SpeedTo(100);
            bot.MoveTo(at.X, at.Y, at.Z - 20);
            Assert.True(bot.WaitForCompletion(OnlineTestSupport.Limit));
            int before = controller.ExecutedIds.Count;
            int lastGood = controller.ExecutedIds[^1];

            // Issued together: the failure of the first cancels the second (ActionFailureTests shows it for a failure applied at once).
            bot.Do(FormattableString.Invariant($"MoveTo(2000, 0, 500); MoveTo({at.X}, {at.Y}, {at.Z});"));
            ActionFailedArgs e = await failed.Task.WaitAsync(Timeout);
            ActionFailedException failure = await Assert.ThrowsAsync<ActionFailedException>(() => bot.WaitForCompletionAsync().WaitAsync(Timeout));

            Assert.Equal(lastGood + 1, e.Action.Id);
            Assert.StartsWith("movel: no inverse kinematics solution: the target pose is out of reach (driver script line ", e.Reason, StringComparison.Ordinal);
            Assert.Same(e.Action, failure.Action);
            Assert.Equal(new[] { lastGood + 2 }, e.CancelledActions.Select(a => a.Id));
            Assert.Empty(bot.GetPendingActions());
            Assert.True(e.Position is Vector stoppedAt && stoppedAt.IsSimilar(at + new Vector(0, 0, -20), 0.05), e.Position?.ToString());
            Assert.Equal(before, controller.ExecutedIds.Count);
            Assert.DoesNotContain(lastGood + 1, executed);
            Assert.DoesNotContain(lastGood + 2, controller.ExecutedIds);
            Assert.Equal(1u, controller.RuntimeState);
            Assert.True(controller.State.Position.IsSimilar(at + new Vector(0, 0, -20), 0.05), controller.State.Position.ToString());
        }
        finally
        {
            await bot.DisconnectAsync();
        }
    }

    private static async Task<byte[]> ReadPackageAsync(NetworkStream stream)
    {
        byte[] size = new byte[4];
        await stream.ReadExactlyAsync(size).AsTask().WaitAsync(Timeout);
        var package = new byte[BinaryPrimitives.ReadInt32BigEndian(size)];
        size.CopyTo(package, 0);
        await stream.ReadExactlyAsync(package.AsMemory(4)).AsTask().WaitAsync(Timeout);
        return package;
    }
}
