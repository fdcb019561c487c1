using System.Buffers.Binary;
using System.Net.Sockets;
using System.Text;
using Machina.Simulation;
using Machina.Tests.Support;

namespace Machina.Tests.Simulation;

/// <summary>
/// The virtual UR's primary, secondary and real-time client interfaces read byte by byte as UR's "Client interfaces" document
/// lays them out (software 5.x), with a reader of this test's own: what UR's client library and ROS driver expect on connect.
/// </summary>
public class UrSimClientInterfaceTests
{
    private static readonly TimeSpan Timeout = TimeSpan.FromSeconds(15);

    private static VirtualUrControllerOptions Options => new()
    {
        InstantExecution = true,
        ControllerVersion = new Version(5, 11, 3, 1234),
        PrimaryPort = 0,
        SecondaryPort = 0,
        RealtimePort = 0,
    };

    [Theory]
    [InlineData(true)]
    [InlineData(false)]
    public async Task PrimaryAndSecondary_OnConnect_SendTheVersionMessageThenRobotState(bool primary)
    {
        await using var controller = new VirtualUrController(Options);
        await controller.StartAsync();
        using var client = await ConnectAsync(primary ? controller.PrimaryPort : controller.SecondaryPort);

        byte[] version = await ReadPackageAsync(client);
        Assert.Equal(20, version[4]); // robot message
        Assert.Equal(0xFE, version[13]); // source -2: the controller
        Assert.Equal(3, version[14]); // version message
        Assert.Equal(9, version[15]);
        Assert.Equal("URControl", Encoding.ASCII.GetString(version, 16, 9));
        Assert.Equal((5, 11), (version[25], version[26]));
        Assert.Equal(3, BinaryPrimitives.ReadInt32BigEndian(version.AsSpan(27))); // bugfix
        Assert.Equal(1234, BinaryPrimitives.ReadInt32BigEndian(version.AsSpan(31))); // build
        Assert.Equal(version.Length, BinaryPrimitives.ReadInt32BigEndian(version));

        byte[] state = await ReadPackageAsync(client);
        Assert.Equal(16, state[4]);
        var subs = SubPackages(state);
        Assert.Equal([(0, 47), (1, 251), (2, 37), (3, 75), (4, 101), (5, 225), (6, 445), (7, 61), (8, 10)], subs.Select(s => (s.Type, s.Bytes.Length)));

        byte[] mode = subs[0].Bytes;
        Assert.Equal([0, 1, 1, 0, 0, 0, 0, 7], mode[13..21]); // simulated, enabled, powered, no stops, no program; running
        byte[] joints = subs[1].Bytes;
        double[] q = [.. Enumerable.Range(0, 6).Select(i => BinaryPrimitives.ReadDoubleBigEndian(joints.AsSpan(5 + i * 41)))];
        Assert.Equal([0, -Math.PI / 2, -Math.PI / 2, -Math.PI / 2, Math.PI / 2, 0], q, new Tolerance(1e-12));
        byte[] cartesian = subs[4].Bytes;
        Vector position = controller.State.Position;
        Assert.Equal(position.X / 1000, BinaryPrimitives.ReadDoubleBigEndian(cartesian.AsSpan(5)), 9);
        Assert.Equal(position.Z / 1000, BinaryPrimitives.ReadDoubleBigEndian(cartesian.AsSpan(21)), 9);
        byte[] kinematics = subs[5].Bytes;
        Assert.Equal(-0.425, BinaryPrimitives.ReadDoubleBigEndian(kinematics.AsSpan(5 + 24 + 48 + 8)), 12); // dh_a[1] of a UR5e
        Assert.Equal(0.1625, BinaryPrimitives.ReadDoubleBigEndian(kinematics.AsSpan(5 + 24 + 96)), 12); // dh_d[0]
    }

    [Fact]
    public async Task Primary_TakesPrimaryCommandsAndScripts_AndReportsThemInState()
    {
        await using var controller = new VirtualUrController(Options);
        await controller.StartAsync();
        using var client = await ConnectAsync(controller.PrimaryPort);
        await ReadPackageAsync(client); // version

        await Send(client, "power off\n");
        await OnlineWait.UntilAsync(() => controller.RobotMode == VirtualUrController.PowerOffMode, "power off");
        await Send(client, "power on\n");
        await OnlineWait.UntilAsync(() => controller.RobotMode == VirtualUrController.IdleMode, "power on: idle");
        await Send(client, "set robotmode run\nset_standard_digital_out(2, True)\n");
        await OnlineWait.UntilAsync(() => controller.RobotMode == VirtualUrController.RunningMode && controller.Twin.Io.GetBit(Machina.Simulation.UrScript.UrIoBanks.StandardOut, 2), "brakes released and output 2 on");

        // The next robot state carries both: mode running, digital output 2 in the masterboard's output bits.
        byte[] masterboard = [];
        await OnlineWait.UntilAsync(() =>
        {
            byte[] state = ReadPackageAsync(client).GetAwaiter().GetResult();
            if (state[4] != 16)
            {
                return false;
            }
            masterboard = SubPackages(state)[3].Bytes;
            return BinaryPrimitives.ReadInt32BigEndian(masterboard.AsSpan(9)) == 1 << 2;
        }, "a robot state with output 2 on");
        Assert.Equal(0, BinaryPrimitives.ReadInt32BigEndian(masterboard.AsSpan(5))); // no input on
        Assert.Empty(controller.Errors); // no command was taken for URScript
    }

    [Fact]
    public async Task Primary_RuntimeErrorAndText_ArriveAsRobotMessages()
    {
        await using var controller = new VirtualUrController(Options);
        await controller.StartAsync();
        using var client = await ConnectAsync(controller.PrimaryPort);
        await ReadPackageAsync(client); // version

        await Send(client, "def p():\n  textmsg(\"hello\")\n  x = [1, 2]\n  textmsg(x[2])\nend\n");
        var messages = new List<(byte Kind, byte[] Bytes)>();
        await OnlineWait.UntilAsync(() =>
        {
            byte[] package = ReadPackageAsync(client).GetAwaiter().GetResult();
            if (package[4] == 20)
            {
                messages.Add((package[14], package));
            }
            return messages.Any(m => m.Kind == 10);
        }, "the runtime exception");
        byte[] text = messages.First(m => m.Kind == 0).Bytes;
        Assert.Contains("hello", Encoding.UTF8.GetString(text, 15, text.Length - 15), StringComparison.Ordinal);
        byte[] error = messages.First(m => m.Kind == 10).Bytes;
        Assert.Equal(4, BinaryPrimitives.ReadInt32BigEndian(error.AsSpan(15))); // the script's line
    }

    [Fact]
    public async Task Realtime_SendsThe1220BytePackageOfSoftware5_WithJointsAndPose()
    {
        await using var controller = new VirtualUrController(Options);
        await controller.StartAsync();
        using var client = await ConnectAsync(controller.RealtimePort);

        byte[] first = await ReadRealtimeAsync(client);
        byte[] second = await ReadRealtimeAsync(client);
        Assert.Equal(1220, first.Length);
        double Value(byte[] p, int index) => BinaryPrimitives.ReadDoubleBigEndian(p.AsSpan(4 + index * 8));
        Assert.True(Value(second, 0) > Value(first, 0), "time goes on");
        Assert.Equal(-Math.PI / 2, Value(first, 1 + 1), 12); // q target, joint 2
        Assert.Equal(-Math.PI / 2, Value(first, 31 + 1), 12); // q actual, joint 2
        Assert.Equal(controller.State.Position.X / 1000, Value(first, 55), 9); // tool vector actual x
        Assert.Equal(7, Value(first, 94)); // robot mode running
        Assert.Equal(1, Value(first, 101)); // safety mode normal
        Assert.Equal(1, Value(first, 131)); // program state: stopped
    }

    [Fact]
    public async Task Realtime_AtSoftware5_Runs500PackagesASecondOnTheControllersClock()
    {
        var clock = new ManualClock();
        await using var controller = new VirtualUrController(Options with { TimeProvider = clock, PrimaryPort = null, SecondaryPort = null });
        await controller.StartAsync();
        using var client = await ConnectAsync(controller.RealtimePort);
        await OnlineWait.UntilAsync(() => controller.RealtimeClients == 1, "the controller to take the client");
        var period = TimeSpan.FromMilliseconds(2);
        var stamps = new List<double>();
        for (int i = 0; i < 5; i++)
        {
            await OnlineWait.UntilAsync(() => clock.HasTimerDueIn(period), "the real-time sender to wait for its next package");
            clock.Advance(period);
            byte[] package = await ReadRealtimeAsync(client);
            stamps.Add(BinaryPrimitives.ReadDoubleBigEndian(package.AsSpan(4)));
        }
        Assert.Equal(Enumerable.Range(1, 5).Select(i => i * 0.002), stamps, new Tolerance(1e-9));
    }

    [Fact]
    public async Task Realtime_WithoutAClient_RunsNoTimer_AndStartsAgainWithTheNextClient()
    {
        var clock = new ManualClock();
        await using var controller = new VirtualUrController(Options with { TimeProvider = clock, PrimaryPort = null, SecondaryPort = null });
        await controller.StartAsync();
        var period = TimeSpan.FromMilliseconds(2);
        using (var first = await ConnectAsync(controller.RealtimePort))
        {
            await OnlineWait.UntilAsync(() => controller.RealtimeClients == 1, "the controller to take the first client");
            await OnlineWait.UntilAsync(() => clock.HasTimerDueIn(period), "the real-time sender to wait for its first package");
            clock.Advance(period);
            Assert.Equal(0.002, BinaryPrimitives.ReadDoubleBigEndian((await ReadRealtimeAsync(first)).AsSpan(4)), 9);
        }
        await OnlineWait.UntilAsync(() => controller.RealtimeClients == 0, "the controller to see the first client leave");
        await OnlineWait.UntilAsync(() => clock.HasTimerDueIn(period), "the real-time sender's next tick");
        clock.Advance(period); // a tick without a client: the sender stops its timer (it ticked on at 500 Hz before)
        await OnlineWait.UntilAsync(() => !clock.HasTimerDueIn(period), "the real-time sender to stop its timer without a client");

        using var second = await ConnectAsync(controller.RealtimePort);
        await OnlineWait.UntilAsync(() => controller.RealtimeClients == 1, "the controller to take the second client");
        await OnlineWait.UntilAsync(() => clock.HasTimerDueIn(period), "the real-time sender to start again");
        clock.Advance(period);
        Assert.Equal(0.006, BinaryPrimitives.ReadDoubleBigEndian((await ReadRealtimeAsync(second)).AsSpan(4)), 9);
    }

    [Theory]
    [InlineData(new[] { "power off\n" }, "", new[] { "power off" })]
    [InlineData(new[] { "po", "wer o", "ff\r\nstopj(2)\n" }, "stopj(2)\n", new[] { "power off" })]
    [InlineData(new[] { "stop", "j(2)\nstop program\n" }, "stopj(2)\n", new[] { "stop program" })]
    [InlineData(new[] { "def p():\n  power_on = 1\nend\n" }, "def p():\n  power_on = 1\nend\n", new string[0])]
    [InlineData(new[] { "set robotmode run\nset unlock protective stop\n" }, "", new[] { "set robotmode run", "set unlock protective stop" })]
    public void PrimaryCommands_AreTakenOutOfTheScriptText_HoweverChunked(string[] chunks, string script, string[] commands)
    {
        var seen = new List<string>();
        var filter = new VirtualUrPrimaryCommands(seen.Add);
        Assert.Equal(script, string.Concat(chunks.Select(filter.Filter)));
        Assert.Equal(commands, seen);
    }

    internal static async Task<TcpClient> ConnectAsync(int port)
    {
        var client = new TcpClient { NoDelay = true };
        await client.ConnectAsync("127.0.0.1", port).WaitAsync(Timeout);
        return client;
    }

    private static Task Send(TcpClient client, string text) => client.GetStream().WriteAsync(Encoding.ASCII.GetBytes(text)).AsTask();

    /// <summary>One primary/secondary package: int32 size (itself included), then the rest.</summary>
    internal static async Task<byte[]> ReadPackageAsync(TcpClient client)
    {
        var size = new byte[4];
        await client.GetStream().ReadExactlyAsync(size).AsTask().WaitAsync(Timeout);
        var package = new byte[BinaryPrimitives.ReadInt32BigEndian(size)];
        size.CopyTo(package, 0);
        await client.GetStream().ReadExactlyAsync(package.AsMemory(4)).AsTask().WaitAsync(Timeout);
        return package;
    }

    private static Task<byte[]> ReadRealtimeAsync(TcpClient client) => ReadPackageAsync(client);

    /// <summary>The sub-packages of a robot state package: each int32 size, uint8 type, content.</summary>
    private static List<(int Type, byte[] Bytes)> SubPackages(byte[] state)
    {
        var subs = new List<(int, byte[])>();
        for (int at = 5; at < state.Length;)
        {
            int size = BinaryPrimitives.ReadInt32BigEndian(state.AsSpan(at));
            subs.Add((state[at + 4], state[at..(at + size)]));
            at += size;
        }
        return subs;
    }

    private sealed class Tolerance(double tolerance) : IEqualityComparer<double>
    {
        public bool Equals(double a, double b) => Math.Abs(a - b) <= tolerance;

        public int GetHashCode(double value) => 0;
    }
}
