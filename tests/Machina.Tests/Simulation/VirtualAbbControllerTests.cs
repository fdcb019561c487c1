using Machina.Simulation;
using Machina.Tests.Support;
using System.Net.Sockets;

namespace Machina.Tests.Simulation;

public class VirtualAbbControllerTests
{
    // These tests check the protocol with raw values (poses outside an IRB 120's reach, joints that do not match the pose),
    // so the controller keeps joints and pose apart; VirtualControllerCoreTests check the robot model.
    // The C# imitation of the driver (RunsRapid = false), kept until it is deleted; VirtualAbbTwinSeamTests test the default.
    private static readonly VirtualAbbControllerOptions Instant = new() { InstantExecution = true, Model = null, RunsRapid = false };

    [Fact]
    public async Task StartAsync_OsChosenPorts_MonitorIsDriverPortPlusOne()
    {
        await using var controller = new VirtualAbbController(Instant);
        await controller.StartAsync();
        Assert.True(controller.Port > 0);
        Assert.Equal(controller.Port + 1, controller.MonitorPort);
        Assert.True(controller.IsRunning);
    }

    [Fact]
    public async Task Connect_Handshake_SendsVersionPoseJointsAndExternalAxes()
    {
        await using var controller = new VirtualAbbController(Instant with
        {
            InitialPosition = new Vector(300, -20.5, 400),
            InitialRotation = Rotation.Identity,
            InitialJoints = new Joints(1, 2, 3, 4, 5, 6),
            InitialExternalAxes = new ExternalAxes(1800),
        });
        await controller.StartAsync();
        using var client = await RawAbbClient.ConnectAsync(controller.Port);
        var messages = await client.ReadHandshakeAsync();
        Assert.Equal(
            "$20 1 6 0;$21 300 -20.5 400 1 0 0 0;$22 1 2 3 4 5 6;$23 1.800E+03 9.000E+09 9.000E+09 9.000E+09 9.000E+09 9.000E+09;$25 0 0;",
            client.RawText);
        Assert.True(messages[0].ToVersion().IsSupported);
        Assert.Equal(new ExternalAxes(1800), messages[3].ToExternalAxes());
    }

    [Fact]
    public async Task Requests_ConcatenatedAndSplit_AcknowledgedInOrderAfterExecution()
    {
        await using var controller = new VirtualAbbController(Instant);
        await controller.StartAsync();
        using var client = await RawAbbClient.ConnectAsync(controller.Port);
        await client.ReadHandshakeAsync();
        await client.SendAsync("@1 4 100;@2 5 0;@3 1 400 0 500 0 0 1 0;@4 3 0 0 0 0 9");
        await client.SendAsync("0 0;@0 15 1800 9E9 9E9 9E9 9E9 9E9;@5 7 \"Hello\";@6 99;");
        var acks = await client.ReadMessagesAsync(7);
        Assert.Equal(["@1 4;", "@2 5;", "@3 1;", "@4 3;", "15;", "@5 7;", "@6 99;"], acks.Select(a => a.ToString()));
        var state = controller.State;
        Assert.Equal(new Vector(400, 0, 500), state.Position);
        Assert.Equal(new Joints(0, 0, 0, 0, 90, 0), state.Joints);
        Assert.Equal((100.0, 0.0), (state.Speed, state.Zone));
        Assert.Equal(new ExternalAxes(1800), state.ExternalAxesCartesian);
        Assert.Contains("Hello", controller.PendantMessages);
        Assert.Contains("Don't understand action code 99", controller.PendantMessages);
        Assert.Equal(7, controller.RequestsReceived);
        Assert.Equal("@4 3 0 0 0 0 90 0;", controller.ReceivedRequests[3]);
    }

    [Fact]
    public async Task Settings_EveryKind_ChangeState()
    {
        await using var controller = new VirtualAbbController(Instant);
        await controller.StartAsync();
        using var client = await RawAbbClient.ConnectAsync(controller.Port);
        await client.ReadHandshakeAsync();
        await client.SendAsync("@1 8 0 0 100 1 0 0 0 0 0 0 50;@2 10 \"DO_1\" 1;@3 11 \"AO_1\" 0.5;@4 13 0.03;@5 16 5 9E9 9E9 9E9 9E9 9E9;@6 18 300 0 300 1 0 0 0;@7 14 1;@8 103 0.05;");
        await client.ReadMessagesAsync(8);
        var s = controller.State;
        Assert.Equal(new Vector(0, 0, 100), s.ToolTcp);
        Assert.Equal(1.0, s.ToolWeight);
        Assert.True(s.DigitalOutputs["DO_1"]);
        Assert.Equal(0.5, s.AnalogOutputs["AO_1"]);
        Assert.Equal(0.03, s.AccelerationLimit);
        Assert.Equal(new ExternalAxes(5), s.ExternalAxesJoints);
        Assert.Equal(new Vector(300, 0, 300), s.WorkObjectOrigin);
        Assert.True(s.WristSingularityArea);
        Assert.Equal(TimeSpan.FromMilliseconds(50), controller.MonitorPeriod);
        await client.SendAsync("@9 9;@10 19;@11 13 0;");
        await client.ReadMessagesAsync(3);
        Assert.Equal((null, null, (double?)null), (controller.State.ToolTcp, controller.State.WorkObjectOrigin, controller.State.AccelerationLimit));
    }

    [Fact]
    public async Task Buffer_HostStreamsFarAhead_HoldsAtMostCapacity()
    {
        await using var controller = new VirtualAbbController(Instant with { BufferCapacity = 3 });
        await controller.StartAsync();
        using var client = await RawAbbClient.ConnectAsync(controller.Port);
        await client.ReadHandshakeAsync();
        controller.StopAnswering();
        await client.SendAsync(string.Concat(Enumerable.Range(1, 10).Select(i => $"@{i} 4 {i};")));
        await RawAbbClient.WaitUntilAsync(() => controller.BufferedRequestCount == 3, "the buffer is full");
        Assert.Equal(0, controller.AcknowledgementsSent);
        Assert.InRange(controller.RequestsReceived, 3, 4);
        controller.ResumeAnswering();
        var acks = await client.ReadMessagesAsync(10);
        Assert.Equal(Enumerable.Range(1, 10), acks.Select(a => a.Id));
        // At most the buffer, the request being executed and one request parsed from the socket before the buffer check.
        Assert.InRange(controller.MaxUnacknowledged, 3, 5);
    }

    [Fact]
    public async Task Motion_WithSpeedFactor_TakesTimeAndMovesThroughIntermediatePoses()
    {
        // 100 mm at 10 mm/s = 10 s of robot time; factor 20 → 0.5 s on the controller's clock, which the test moves.
        var clock = new ManualClock();
        await using var controller = new VirtualAbbController(new VirtualAbbControllerOptions
        {
            RunsRapid = false,
            Model = null,
            InitialPosition = new Vector(0, 0, 0),
            InitialRotation = Rotation.Identity,
            SpeedFactor = 20,
            TimeProvider = clock,
        });
        await controller.StartAsync();
        using var client = await RawAbbClient.ConnectAsync(controller.Port);
        await client.ReadHandshakeAsync();
        await client.SendAsync("@1 4 10;@2 1 100 0 0 1 0 0 0;");
        Assert.Equal(1, (await client.ReadMessagesAsync(1))[0].Id);
        await RawAbbClient.WaitUntilAsync(() => clock.HasTimerDueIn(TimeSpan.FromSeconds(0.5)), "the move to start");

        clock.Advance(TimeSpan.FromSeconds(0.2));
        Assert.Equal(new Vector(40, 0, 0), controller.State.Position);
        Assert.Equal(1, controller.AcknowledgementsSent);
        clock.Advance(TimeSpan.FromSeconds(0.2));
        Assert.Equal(new Vector(80, 0, 0), controller.State.Position);
        Assert.Equal(1, controller.AcknowledgementsSent);
        clock.Advance(TimeSpan.FromSeconds(0.1));

        Assert.Equal(2, (await client.ReadMessagesAsync(1))[0].Id);
        Assert.Equal(new Vector(100, 0, 0), controller.State.Position);
    }

    [Fact]
    public async Task Monitor_Connected_ReportsFullPoseInThreeChunks()
    {
        await using var controller = new VirtualAbbController(Instant with
        {
            InitialPosition = new Vector(1, 2, 3),
            InitialRotation = Rotation.Identity,
            MonitorPeriod = TimeSpan.FromMilliseconds(5),
        });
        await controller.StartAsync();
        using var monitor = await RawAbbClient.ConnectAsync(controller.MonitorPort);
        var reports = await monitor.ReadMessagesAsync(3);
        Assert.StartsWith("$24 1 2 3 1 0 0 0>0 0 0 0 90 0>9.000E+09 ", monitor.RawText, StringComparison.Ordinal);
        var update = reports[2].ToMonitorUpdate();
        Assert.Equal((new Vector(1, 2, 3), new Joints(0, 0, 0, 0, 90, 0), ExternalAxes.None), (update.Position, update.Joints, update.ExternalAxes));
        Assert.True(controller.MonitorReportsSent >= 3);
    }

    [Fact]
    public async Task Fault_CloseAfterAcknowledgements_ClosesSocketAndAcceptsNewClient()
    {
        await using var controller = new VirtualAbbController(Instant);
        await controller.StartAsync();
        using (var client = await RawAbbClient.ConnectAsync(controller.Port))
        {
            await client.ReadHandshakeAsync();
            controller.CloseConnectionAfter(2);
            await client.SendAsync("@1 4 10;@2 4 20;@3 4 30;");
            Assert.Equal("@1 4;@2 4;", await client.ReadToEndAsync());
        }
        using var second = await RawAbbClient.ConnectAsync(controller.Port);
        Assert.Equal(20, (await second.ReadHandshakeAsync())[0].Code);
        Assert.Equal(2, controller.ConnectionCount);
        await RawAbbClient.WaitUntilAsync(() => controller.RequestsExecuted == 3, "the buffered request is executed");
        Assert.Equal(30, controller.State.Speed);
    }

    [Fact]
    public async Task Fault_GarbageAndUnknownId_ReachTheHostReader()
    {
        await using var controller = new VirtualAbbController(Instant);
        await controller.StartAsync();
        using var client = await RawAbbClient.ConnectAsync(controller.Port);
        await client.ReadHandshakeAsync();
        Assert.True(await controller.SendAcknowledgementAsync(4242, 1));
        Assert.Equal(new AbbAcknowledgement(4242, 1), (await client.ReadMessagesAsync(1))[0].ToAcknowledgement());
        Assert.True(await controller.SendRawAsync("#!garbage;"));
        var e = await Assert.ThrowsAsync<AbbProtocolException>(() => client.ReadMessagesAsync(1));
        Assert.Equal("#!garbage;", e.ReceivedText);
    }

    [Fact]
    public async Task Fault_StopAnswering_NoAcknowledgementUntilResumed()
    {
        await using var controller = new VirtualAbbController(Instant);
        await controller.StartAsync();
        using var client = await RawAbbClient.ConnectAsync(controller.Port);
        await client.ReadHandshakeAsync();
        controller.StopAnswering();
        await client.SendAsync("@1 4 10;");
        await RawAbbClient.WaitUntilAsync(() => controller.BufferedRequestCount == 1, "the request is buffered");
        Assert.Equal((0, 1), (controller.AcknowledgementsSent, controller.RequestsReceived));
        controller.ResumeAnswering();
        Assert.Equal(1, (await client.ReadMessagesAsync(1))[0].Id);
    }

    [Fact]
    public async Task MalformedRequest_LikeStrictDriver_RecordsErrorAndDropsClient()
    {
        await using var controller = new VirtualAbbController(Instant);
        await controller.StartAsync();
        using var client = await RawAbbClient.ConnectAsync(controller.Port);
        await client.ReadHandshakeAsync();
        await client.SendAsync("@1 4 fast;");
        Assert.Equal("", await client.ReadToEndAsync());
        Assert.Equal(["received corrupt parameter \"fast\""], controller.Errors);
    }

    [Fact]
    public async Task StopExecution_Code100_AcknowledgesThenEndsProgram()
    {
        await using var controller = new VirtualAbbController(Instant);
        await controller.StartAsync();
        using var client = await RawAbbClient.ConnectAsync(controller.Port);
        await client.ReadHandshakeAsync();
        await client.SendAsync("@9 100;");
        Assert.Equal("@9 100;", await client.ReadToEndAsync());
        await Assert.ThrowsAnyAsync<SocketException>(async () => (await RawAbbClient.ConnectAsync(controller.Port)).Dispose());
    }

    [Fact]
    public async Task GetInfo_Code101_SendsInformationBeforeAcknowledgement()
    {
        await using var controller = new VirtualAbbController(Instant);
        await controller.StartAsync();
        using var client = await RawAbbClient.ConnectAsync(controller.Port);
        await client.ReadHandshakeAsync();
        await client.SendAsync("@3 101 1;");
        var messages = await client.ReadMessagesAsync(2);
        Assert.Equal((AbbMessageKind.Information, "1 1.6.0"), (messages[0].Kind, messages[0].Text));
        Assert.Equal(new AbbAcknowledgement(3, 101), messages[1].ToAcknowledgement());
    }

    [Fact]
    public async Task StopAsync_WithConnectedClients_EndsCleanly()
    {
        var controller = new VirtualAbbController(Instant);
        await controller.StartAsync();
        using var client = await RawAbbClient.ConnectAsync(controller.Port);
        using var monitor = await RawAbbClient.ConnectAsync(controller.MonitorPort);
        await client.ReadHandshakeAsync();
        await monitor.ReadMessagesAsync(1);
        controller.StopAnswering();
        await client.SendAsync("@1 4 10;");
        var stop = controller.StopAsync();
        Assert.Same(stop, await Task.WhenAny(stop, Task.Delay(RawAbbClient.Timeout)));
        await stop;
        Assert.False(controller.IsRunning);
        await controller.DisposeAsync();
    }

    [Fact]
    public void Constructor_InvalidOptions_Throws()
    {
        Assert.Throws<ArgumentException>(() => new VirtualAbbController(new VirtualAbbControllerOptions { SpeedFactor = 0 }));
        Assert.Throws<ArgumentException>(() => new VirtualAbbController(new VirtualAbbControllerOptions { BufferCapacity = 0 }));
    }
}
