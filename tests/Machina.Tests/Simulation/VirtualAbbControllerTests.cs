using Machina.Simulation;
using Machina.Tests.Support;
using System.Net.Sockets;

namespace Machina.Tests.Simulation;

public class VirtualAbbControllerTests
{
    // The controller's own surface (ports, faults, stopping) around the RAPID driver it runs; VirtualAbbTwinSeamTests and
    // AbbRapidTwinOnlineTests test what the driver does.
    private static readonly VirtualAbbControllerOptions Instant = new() { InstantExecution = true, Model = null };

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
    public async Task ListenPort_ListensThereItself_TellsEachHostThatConnectsAndLeaves()
    {
        var seen = new System.Collections.Concurrent.ConcurrentQueue<string>();
        (TcpListener free, TcpListener next) = LoopbackPorts.BindPair();
        int port = ((System.Net.IPEndPoint)free.LocalEndpoint).Port;
        free.Stop();
        next.Stop();
        await using var controller = new VirtualAbbController(Instant with
        {
            ListenAddress = System.Net.IPAddress.Loopback,
            ListenPort = port,
            ConnectionSeen = (name, who, connected) => seen.Enqueue($"{name} {(connected ? "connected" : "left")} {who.StartsWith("127.0.0.1:", StringComparison.Ordinal)}"),
        });
        await controller.StartAsync();
        Assert.Equal((port, port + 1), (controller.Port, controller.MonitorPort));
        using (var client = await RawAbbClient.ConnectAsync(port))
        {
            await client.ReadHandshakeAsync();
        }

        await RawAbbClient.WaitUntilAsync(() => seen.Count >= 2, "the host to be seen leaving");
        Assert.Equal(["driver connected True", "driver left True"], seen.ToArray());
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
        Assert.Equal([1, 2, 3], controller.ExecutedIds);
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
    public async Task StopExecution_Code100_AcknowledgesThenEndsProgram()
    {
        await using var controller = new VirtualAbbController(Instant);
        await controller.StartAsync();
        using var client = await RawAbbClient.ConnectAsync(controller.Port);
        await client.ReadHandshakeAsync();
        await client.SendAsync("@9 100;");
        Assert.Equal("@9 100;", await client.ReadToEndAsync());
        // The program closes the host's socket, then its listening one, and ends: a connection tried in between still gets in.
        bool refused = false;
        for (DateTime deadline = DateTime.UtcNow + TimeSpan.FromSeconds(10); !refused && DateTime.UtcNow < deadline;)
        {
            try
            {
                (await RawAbbClient.ConnectAsync(controller.Port)).Dispose();
                await Task.Delay(10);
            }
            catch (SocketException)
            {
                refused = true;
            }
        }
        Assert.True(refused, "the driver program still takes connections 10 s after the stop");
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
        Assert.Equal((AbbMessageKind.Information, "1 1.7.0"), (messages[0].Kind, messages[0].Text));
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
        Assert.Equal("The virtual ABB always runs the RAPID driver (its C# imitation was removed): leave RunsRapid true. (Parameter 'RunsRapid')",
            Assert.Throws<ArgumentException>(() => new VirtualAbbController(new VirtualAbbControllerOptions { RunsRapid = false })).Message);
        Assert.Equal("The virtual ABB's arm has no external axes (the RAPID twin reports 9E9): leave InitialExternalAxes at none. (Parameter 'InitialExternalAxes')",
            Assert.Throws<ArgumentException>(() => new VirtualAbbController(new VirtualAbbControllerOptions { InitialExternalAxes = new ExternalAxes(1800) })).Message);
        Assert.Equal("The virtual ABB runs Machina's RAPID driver 1.7.0 or an older 1.x as it spoke, not 1.8.0. (Parameter 'DriverVersion')",
            Assert.Throws<ArgumentException>(() => new VirtualAbbController(new VirtualAbbControllerOptions { DriverVersion = new Version(1, 8, 0) })).Message);
        Assert.Throws<ArgumentException>(() => new VirtualAbbController(new VirtualAbbControllerOptions { BufferCapacity = 0 }));
    }
}
