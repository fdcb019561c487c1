using Machina.Simulation;

namespace Machina.Tests.Simulation;

/// <summary>
/// The virtual ABB runs Machina's RAPID driver by default; its faults and inspection act on the driver task's socket: what
/// SocketReceive read is received, what the driver acknowledged with SocketSend is executed, and the fault plan sits on that write.
/// </summary>
public class VirtualAbbTwinSeamTests
{
    private static readonly VirtualAbbControllerOptions Instant = new() { InstantExecution = true };

    [Fact]
    public async Task Default_RunsTheDriverModuleOnAnIrb120_HandshakeFromRapid()
    {
        Assert.True(Instant.RunsRapid);
        await using var controller = new VirtualAbbController(Instant);
        await controller.StartAsync();
        using var client = await RawAbbClient.ConnectAsync(controller.Port);
        var messages = await client.ReadHandshakeAsync();

        Assert.Equal("IRB 120", controller.Twin!.Arm.Model.Name);
        Assert.StartsWith("$20 1 7 0;", client.RawText, StringComparison.Ordinal);
        Assert.Equal(new Joints(0, 0, 0, 0, 90, 0), messages[2].ToJoints());
        Assert.Equal(new Vector(302, 0, 558), messages[1].ToPose().Position);
        Assert.Equal(1, controller.ConnectionCount);
    }

    [Fact]
    public async Task Requests_ReadAndAcknowledgedByTheDriver_CountedLoggedAndExecutedInOrder()
    {
        await using var controller = new VirtualAbbController(Instant);
        await controller.StartAsync();
        using var client = await RawAbbClient.ConnectAsync(controller.Port);
        await client.ReadHandshakeAsync();
        await client.SendAsync("@1 4 100;@2 5 0;@3 1 400 0 300 0 0 1 0;@4 7 \"a;b\";@0 9;");
        var acks = await client.ReadMessagesAsync(5);

        Assert.Equal(["@1 4;", "@2 5;", "@3 1;", "@4 7;", "9;"], acks.Select(a => a.ToString()));
        Assert.Equal([1, 2, 3, 4], controller.ExecutedIds); // id 0 is acknowledged, never logged
        Assert.Equal(["@1 4 100;", "@2 5 0;", "@3 1 400 0 300 0 0 1 0;", "@4 7 \"a;b\";", "@0 9;"], controller.ReceivedRequests);
        Assert.Equal((5, 5, 5), (controller.RequestsReceived, controller.RequestsExecuted, controller.AcknowledgementsSent));
        Assert.Equal(400, controller.State.Position.X, 3);
        Assert.Equal(300, controller.State.Position.Z, 3);
        Assert.Contains("a;b", controller.PendantMessages);
    }

    [Fact]
    public async Task StopAnswering_DriverHeldAtItsAcknowledgement_UntilResumed()
    {
        await using var controller = new VirtualAbbController(Instant);
        await controller.StartAsync();
        using var client = await RawAbbClient.ConnectAsync(controller.Port);
        await client.ReadHandshakeAsync();
        controller.StopAnswering();
        await client.SendAsync("@1 4 10;");
        await RawAbbClient.WaitUntilAsync(() => controller.BufferedRequestCount == 1, "the request is read by the driver");

        Assert.Equal((0, 1), (controller.AcknowledgementsSent, controller.RequestsReceived));
        controller.ResumeAnswering();
        Assert.Equal(1, (await client.ReadMessagesAsync(1))[0].Id);
        Assert.Equal([1], controller.ExecutedIds);
    }

    [Fact]
    public async Task CloseAfterOneAcknowledgement_DriverAcceptsTheNextClient_ProgressInItsHandshake()
    {
        await using var controller = new VirtualAbbController(Instant);
        await controller.StartAsync();
        using (var first = await RawAbbClient.ConnectAsync(controller.Port))
        {
            await first.ReadHandshakeAsync();
            controller.CloseConnectionAfter(1);
            await first.SendAsync("@1 4 10;");
            Assert.Equal(1, (await first.ReadMessagesAsync(1))[0].Id);
            Assert.Equal("", await first.ReadToEndAsync());
        }
        // The driver closes its server socket and listens again (ServerStart): connect once it says it waits again.
        await RawAbbClient.WaitUntilAsync(() => controller.PendantMessages.Count(m => m.StartsWith("Machina driver waiting for a client", StringComparison.Ordinal)) == 2, "the driver to listen again");
        using var second = await RawAbbClient.ConnectAsync(controller.Port);
        var handshake = await second.ReadHandshakeAsync();

        Assert.Equal(new DeviceProgress(1, 1), handshake[4].ToProgress());
        Assert.Equal(2, controller.ConnectionCount);
        Assert.Contains("Machina client disconnected", controller.PendantMessages);
    }

    [Fact]
    public async Task RefuseConnections_TheFirstIsClosed_TheDriverServesTheNext()
    {
        await using var controller = new VirtualAbbController(Instant with { Faults = new VirtualFaults { RefuseConnections = 1 } });
        await controller.StartAsync();
        using (var refused = await RawAbbClient.ConnectAsync(controller.Port))
        {
            Assert.Equal("", await refused.ReadToEndAsync());
        }
        using var client = await RawAbbClient.ConnectAsync(controller.Port);
        var handshake = await client.ReadHandshakeAsync();

        Assert.True(handshake[0].ToVersion().IsSupported);
        Assert.Equal(1, controller.ConnectionCount);
        Assert.Contains("fault: connection refused", controller.PendantMessages);
    }

    [Fact]
    public async Task GarbageAfterFirstAcknowledgement_GoesOnTheDriverSocket_ThenTheAcknowledgement()
    {
        await using var controller = new VirtualAbbController(Instant with { Faults = new VirtualFaults { After = 1, Kinds = [VirtualFault.Garbage] } });
        await controller.StartAsync();
        using var client = await RawAbbClient.ConnectAsync(controller.Port);
        await client.ReadHandshakeAsync();
        await client.SendAsync("@1 4 10;");
        var e = await Assert.ThrowsAsync<AbbProtocolException>(() => client.ReadMessagesAsync(1));

        Assert.StartsWith("#", e.ReceivedText, StringComparison.Ordinal);
        Assert.EndsWith(";", e.ReceivedText, StringComparison.Ordinal);
        Assert.Equal([VirtualFault.Garbage], controller.InjectedFaults);
    }
}
