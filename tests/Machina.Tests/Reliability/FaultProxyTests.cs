using Machina.Simulation;
using Machina.Tests.Support;
using static Machina.Tests.Online.OnlineTestSupport;

namespace Machina.Tests.Reliability;

/// <summary>
/// Faults of the network between host and controller, made by a <see cref="FaultProxy"/> in front of an unmodified virtual
/// controller: bytes split one by one and delayed, connections cut at a seeded byte, garbage injected towards the host.
/// The program still runs exactly once, in order, and ends at the right pose.
/// </summary>
public class FaultProxyTests
{
    private const int Actions = 40;
    private static readonly Vector End = new(300, 100, 400 + 5 * (Actions - 1));

    [Theory]
    [InlineData("ABB")]
    [InlineData("UR")]
    [InlineData("KUKA")]
    public async Task SplitIntoBytesAndDelayed_EveryChannel_EveryActionOnceWithoutFault(string brand)
    {
        await using var rig = await FaultRig.StartAsync(brand, new VirtualFaults());
        await using var proxy = FaultProxy.Start(rig.ProxiedPorts, new FaultProxyOptions { Seed = 14301, SplitIntoBytes = true, MaxDelay = TimeSpan.FromMilliseconds(2) });
        var w = rig.CreateRobot(port: proxy.Port);
        await w.Bot.ConnectAsync("127.0.0.1", proxy.Port).WaitAsync(Limit);
        FaultMatrixTests.IssueProgram(w.Bot);

        int recoveries = await rig.RunToCompletionAsync(w, Limit, maxRecoveries: 0);

        Assert.Equal(0, recoveries);
        Assert.Empty(w.Faults);
        AssertExactlyOnce(rig, w);
        Assert.True(proxy.Accepted >= 1);
        await w.Bot.DisconnectAsync();
    }

    /// <summary>
    /// The driver connection cut twice at a seeded byte towards the host: the first connection while it streams (past its
    /// handshake, before its last acknowledgement: ABB's former imitation sent 352 bytes and KUKA 723 for the whole program), the
    /// second inside its handshake (under 100 bytes). Each cut is reported, and reconnecting through the proxy resumes.
    /// </summary>
    [Theory]
    [InlineData("ABB")]
    [InlineData("KUKA")]
    public async Task DriverConnectionCut_ReconnectThroughTheProxy_EveryActionOnce(string brand)
    {
        await using var rig = await FaultRig.StartAsync(brand, new VirtualFaults());
        await using var proxy = FaultProxy.Start(rig.ProxiedPorts, new FaultProxyOptions { Seed = 14302, CloseConnections = 2, CloseAfterBytes = [Streaming(brand), (40, 100)] });
        var w = rig.CreateRobot(port: proxy.Port);
        FaultMatrixTests.IssueProgram(w.Bot);

        await rig.RecoverAsync(w);
        await rig.RunToCompletionAsync(w, Limit, maxRecoveries: 3);

        AssertExactlyOnce(rig, w);
        Assert.True(2 == proxy.Closed, $"closed {proxy.Closed}, accepted {proxy.Accepted}, towards the host {string.Join(' ', proxy.BytesTowardsHost)}");
        MachinaException[] reported = [.. w.Faults, .. w.RecoveryErrors];
        Assert.Equal(2, reported.Length);
        Assert.Single(w.Faults); // the cut while streaming; the one inside the handshake made Connect fail
        Assert.Single(w.RecoveryErrors);
        Assert.All(reported, e => Assert.IsType<RobotConnectionException>(e));
        Assert.All(reported, e => Assert.Matches("closed the connection|failed", e.Message));
        await w.Bot.DisconnectAsync();
    }

    /// <summary>Garbage injected into the driver connection at a seeded byte: a protocol error naming what was received, then a clean resume.</summary>
    [Theory]
    [InlineData("ABB", "#garbage;")]
    [InlineData("KUKA", "<Garbage></Garbage>")]
    public async Task GarbageTowardsTheHost_ProtocolErrorThenResume_EveryActionOnce(string brand, string garbage)
    {
        await using var rig = await FaultRig.StartAsync(brand, new VirtualFaults());
        await using var proxy = FaultProxy.Start(rig.ProxiedPorts, new FaultProxyOptions
        {
            Seed = 14303, GarbageConnections = 1, CloseAfterBytes = [Streaming(brand)], Garbage = System.Text.Encoding.ASCII.GetBytes(garbage),
        });
        var w = rig.CreateRobot(port: proxy.Port);
        FaultMatrixTests.IssueProgram(w.Bot);

        await rig.RecoverAsync(w);
        await rig.RunToCompletionAsync(w, Limit, maxRecoveries: 3);

        AssertExactlyOnce(rig, w);
        Assert.True(1 == proxy.GarbageInjected, $"garbage {proxy.GarbageInjected}, accepted {proxy.Accepted}, towards the host {string.Join(' ', proxy.BytesTowardsHost)}");
        MachinaException reported = Assert.Single([.. w.Faults, .. w.RecoveryErrors]);
        Assert.IsType(brand == "ABB" ? typeof(AbbProtocolException) : typeof(KukaProtocolException), reported);
        await w.Bot.DisconnectAsync();
    }

    /// <summary>UR: the RTDE connection cut mid-program only costs the live state (a warning); the driver link carries on.</summary>
    [Fact]
    public async Task UrRtdeCut_StreamingGoesOn_EveryActionOnce()
    {
        await using var rig = await FaultRig.StartAsync("UR", new VirtualFaults());
        await using var proxy = FaultProxy.Start(rig.ProxiedPorts, new FaultProxyOptions { Seed = 14304, FaultChannel = 1, CloseConnections = 1, CloseAfterBytes = [(2000, 2000)] });
        var w = rig.CreateRobot(port: proxy.Port);
        await rig.RecoverAsync(w); // connects, again if the cut came while connecting
        await EventuallyAsync(() => proxy.Closed == 1, "the RTDE connection to be cut");
        FaultMatrixTests.IssueProgram(w.Bot);

        await rig.RunToCompletionAsync(w, Limit, maxRecoveries: 0);

        Assert.Empty(w.Faults);
        AssertExactlyOnce(rig, w);
        await w.Bot.DisconnectAsync();
    }

    /// <summary>
    /// Bytes towards the host after the handshake and before the last acknowledgement of the 40-action program: the RAPID
    /// driver's handshake is 88 bytes and its acknowledgements 5 or 6 (240 in all); KUKA's state is about 250 bytes and its
    /// acknowledgements 15 or 16 (723 in all).
    /// </summary>
    private static (int Min, int Max) Streaming(string brand) => brand == "ABB" ? (100, 230) : (450, 600);


    private static void AssertExactlyOnce(FaultRig rig, FaultRig.Watched w)
    {
        Assert.Equal(Enumerable.Range(1, Actions), w.Executed);
        Assert.Equal(Enumerable.Range(1, Actions), rig.ExecutedIds);
        Assert.True(rig.Position.IsSimilar(End, 1e-6), $"{rig.Brand} ended at {rig.Position}, expected {End}");
        Assert.Empty(rig.Errors);
    }
}
