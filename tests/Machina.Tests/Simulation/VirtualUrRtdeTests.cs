using Machina.Simulation;
using Machina.Tests.Support;

namespace Machina.Tests.Simulation;

/// <summary>The virtual UR's RTDE server read by a client written from UR's RTDE guide (no shared code).</summary>
public class VirtualUrRtdeTests
{
    [Fact]
    public async Task Rtde_GuideClient_NegotiatesSubscribesAndReadsPoseAndJoints()
    {
        await using var controller = new VirtualUrController(new VirtualUrControllerOptions { InstantExecution = true, ControllerVersion = new Version(5, 9, 4) });
        await controller.StartAsync();
        using var client = await GuideRtdeClient.ConnectAsync(controller.RtdePort);

        Assert.True(await client.NegotiateAsync());
        Assert.Equal(new uint[] { 5, 9, 4, 0 }, await client.ControllerVersionAsync());
        string[] types = await client.SetupOutputsAsync(125, "timestamp", "actual_TCP_pose", "actual_q", "robot_mode", "safety_status", "runtime_state", "no_such_value");
        Assert.Equal(["DOUBLE", "VECTOR6D", "VECTOR6D", "INT32", "INT32", "UINT32", "NOT_FOUND"], types);
        Assert.False(await client.StartAsync()); // a recipe with an unknown name cannot start

        await client.SetupOutputsAsync(125, "actual_TCP_pose", "actual_q", "robot_mode", "safety_status", "runtime_state");
        Assert.True(await client.StartAsync());
        var data = await client.ReadDataAsync();

        var state = controller.State;
        var pose = (double[])data["actual_TCP_pose"];
        var q = (double[])data["actual_q"];
        Assert.True(new Vector(pose[0] * 1000, pose[1] * 1000, pose[2] * 1000).IsSimilar(state.Position, 1e-9));
        Assert.True(Rotation.FromRotationVector(new Vector(pose[3], pose[4], pose[5]) * (180 / Math.PI)).IsSimilar(state.Rotation, 1e-9));
        Assert.Equal(state.Joints, Joints.FromArray(q.Select(r => r * 180 / Math.PI).ToArray()), new JointsComparer());
        Assert.Equal(-Math.PI / 2, q[1], 12);
        Assert.Equal((7L, 1L, 1L), ((long)data["robot_mode"], (long)data["safety_status"], (long)data["runtime_state"])); // running, normal, stopped (no program)
    }

    [Theory]
    [InlineData(0, 0)]
    [InlineData(-5_000, 0)]
    [InlineData(6_667, 10_000)] // 0.67 ms: Task.Delay would make it 0 and the sender would spin without the clock moving
    [InlineData(16_667, 20_000)]
    [InlineData(200_000, 200_000)]
    public void Rtde_SenderWait_IsRoundedUpToWholeMilliseconds(long ticks, long expected) =>
        Assert.Equal(TimeSpan.FromTicks(expected), VirtualUrController.WholeMillisecondsUp(TimeSpan.FromTicks(ticks)));

    [Fact]
    public async Task Rtde_ManualClock_PackagesAtTheConfiguredRate()
    {
        var clock = new ManualClock();
        await using var controller = new VirtualUrController(new VirtualUrControllerOptions { InstantExecution = true, TimeProvider = clock });
        await controller.StartAsync();
        using var client = await GuideRtdeClient.ConnectAsync(controller.RtdePort);
        Assert.True(await client.NegotiateAsync());
        await client.SetupOutputsAsync(25, "timestamp");
        Assert.True(await client.StartAsync());
        double first = (double)(await client.ReadDataAsync())["timestamp"];
        var period = TimeSpan.FromMilliseconds(40);

        // One simulated second, one period at a time: each step is due exactly one package.
        var stamps = new List<double>();
        for (int i = 0; i < 25; i++)
        {
            await OnlineWait.UntilAsync(() => clock.HasTimerDueIn(period), "the sender to wait for its next package");
            clock.Advance(period);
            stamps.Add((double)(await client.ReadDataAsync())["timestamp"]);
        }
        Assert.Equal(26, controller.RtdePackagesSent);
        Assert.Equal(Enumerable.Range(1, 25).Select(i => first + i * 0.04), stamps, new ToleranceComparer(1e-9));
    }

    private sealed class JointsComparer : IEqualityComparer<Joints>
    {
        public bool Equals(Joints a, Joints b) => a.IsSimilar(b, 1e-9);

        public int GetHashCode(Joints j) => 0;
    }

    private sealed class ToleranceComparer(double tolerance) : IEqualityComparer<double>
    {
        public bool Equals(double a, double b) => Math.Abs(a - b) <= tolerance;

        public int GetHashCode(double d) => 0;
    }
}

/// <summary>A bounded wait for a condition another thread makes true.</summary>
internal static class OnlineWait
{
    internal static async Task UntilAsync(Func<bool> condition, string what)
    {
        long start = TimeProvider.System.GetTimestamp();
        while (!condition())
        {
            Assert.True(TimeProvider.System.GetElapsedTime(start) < TimeSpan.FromSeconds(15), "Timed out waiting for " + what);
            await Task.Delay(2);
        }
    }
}
