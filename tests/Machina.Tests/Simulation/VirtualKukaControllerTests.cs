using System.Net;
using System.Net.Sockets;
using System.Text;
using Machina.Simulation;
using Machina.Tests.Online;
using Machina.Tests.Support;

namespace Machina.Tests.Simulation;

/// <summary>The virtual KUKA controller spoken to with raw bytes: what it sends on a connection, and what it refuses.</summary>
public class VirtualKukaControllerTests
{
    private static readonly TimeSpan Timeout = TimeSpan.FromSeconds(10);

    [Fact]
    public async Task Connect_SendsItsStateWithTheModelsPoseAndNoProgress()
    {
        await using var controller = await KukaTestSupport.StartKukaAsync();
        using var client = await KukaTestSupport.ConnectRawAsync(controller.Port);
        KukaElement state = await KukaTestSupport.ReadElementAsync(client, new KukaXmlReader());

        Pose flange = RobotModels.Get("KR 6 R900 sixx").Kinematics.Forward(new Joints(0, -90, 90, 0, 90, 0));
        Assert.Equal(KukaMessages.State(new Joints(0, -90, 90, 0, 90, 0), flange.Position, flange.Rotation, 0, 0, "#KR6R900SIXX C4"), state.ToString().Replace("/>", "></S>", StringComparison.Ordinal));
        Assert.Equal(new DeviceProgress(0, 0), KukaState.Parse(state).Progress);
        // The arm's $MODEL_NAME[], which the host maps to the catalogue model.
        Assert.Equal("KR 6 R900 sixx", KukaState.Parse(state).ToHandshake().Model?.Name);
    }

    [Fact]
    public async Task SpeedFactor1000_TheSubmitInterpreterCyclesOnTheWallClock_MonitorReportsAtMostEvery4Ms()
    {
        // At 1000x a cycle of the scaled clock was 4 µs: the monitor sent a report in nearly every one (thousands a second).
        await using var controller = await KukaTestSupport.StartKukaAsync(new VirtualKukaControllerOptions { SpeedFactor = 1000 });
        using var monitor = await KukaTestSupport.ConnectRawAsync(controller.MonitorPort);
        await Eventually.TrueAsync(() => controller.MonitorReportsSent > 0, "the first report", Timeout);
        int first = controller.MonitorReportsSent;
        var watch = System.Diagnostics.Stopwatch.StartNew();
        await Task.Delay(400);
        int reports = controller.MonitorReportsSent - first;
        double allowed = watch.Elapsed.TotalMilliseconds / KukaSubmitCycleMs + 2;

        Assert.True(reports <= allowed, $"{reports} reports in {watch.Elapsed.TotalMilliseconds:0} ms (at most {allowed:0})");
    }

    private const double KukaSubmitCycleMs = 4;

    [Fact]
    public async Task ListenPort_ListensThereItself_TellsEachHostThatConnectsAndLeaves()
    {
        var seen = new System.Collections.Concurrent.ConcurrentQueue<string>();
        int port = FreePortPair();
        await using var controller = await KukaTestSupport.StartKukaAsync(new VirtualKukaControllerOptions
        {
            ListenAddress = IPAddress.Loopback,
            ListenPort = port,
            ConnectionSeen = (name, who, connected) => seen.Enqueue($"{name} {(connected ? "connected" : "left")} {who.StartsWith("127.0.0.1:", StringComparison.Ordinal)}"),
        });
        Assert.Equal((port, port + 1), (controller.Port, controller.MonitorPort));
        using (var client = await KukaTestSupport.ConnectRawAsync(port))
        {
            await KukaTestSupport.ReadElementAsync(client, new KukaXmlReader());
        }

        await Eventually.TrueAsync(() => seen.Count >= 2, "the host to be seen leaving", Timeout);
        Assert.Equal(["driver connected True", "driver left True"], seen.ToArray());
    }

    /// <summary>A port P with P + 1 free too, as the system chooses them (released before use: another program could take them, rarely).</summary>
    private static int FreePortPair()
    {
        (TcpListener driver, TcpListener monitor) = LoopbackPorts.BindPair();
        int port = ((IPEndPoint)driver.LocalEndpoint).Port;
        driver.Stop();
        monitor.Stop();
        return port;
    }

    [Fact]
    public void Options_ImitationOrAnotherDriverVersion_RefusedSayingTheTwinRunsOnlyTheShippedDriver()
    {
        var imitation = Assert.Throws<ArgumentException>(() => new VirtualKukaController(new VirtualKukaControllerOptions { RunsKrl = false }));
        Assert.Equal("The virtual KUKA runs only Machina's KRL driver (drivers/kuka) on its KRL interpreter; the C# imitation of the driver (RunsKrl = false) was removed. (Parameter 'RunsKrl')", imitation.Message);
        var older = Assert.Throws<ArgumentException>(() => new VirtualKukaController(new VirtualKukaControllerOptions { DriverVersion = new Version(1, 0) }));
        Assert.Equal("The virtual KUKA runs the shipped KRL driver, version 2.1, or an older 2.x as it greeted a host, not 1.0. (Parameter 'DriverVersion')", older.Message);
    }

    /// <summary>The driver's quit message for <paramref name="text"/>, as the smartPAD's message window shows it (80 characters at most).</summary>
    private static string Quit(string text) => "QUIT Machina 2: " + text[..Math.Min(80, text.Length)];

    [Fact]
    public async Task Batch_MoreActionsThanTheRingHolds_DriverQuitsAndHaltsBeforeRunningAny()
    {
        await using var controller = await KukaTestSupport.StartKukaAsync();
        controller.StopAnswering();
        using var client = await KukaTestSupport.ConnectRawAsync(controller.Port);
        await KukaTestSupport.ReadElementAsync(client, new KukaXmlReader());
        var sb = new StringBuilder();
        KukaInstruction.AppendBatch(sb, Enumerable.Range(1, KukaProtocol.Capacity + 1).Select(id => new KukaInstruction(id, KukaActionCode.Wait, new KukaValues(), "")));
        await client.GetStream().WriteAsync(Encoding.ASCII.GetBytes(sb.ToString()));

        // machina_take finds slot 1 still holding action 1 when it reaches action 101: the driver stops rather than overwrite it.
        await Eventually.TrueAsync(() => controller.PendantMessages.Contains(Quit("Machina sent more than 100 actions not executed yet; the driver stops.")), "the quit message", Timeout);
        Assert.Equal(KukaProtocol.Capacity + 1, controller.RequestsReceived);
        controller.ResumeAnswering();
        Assert.Empty(controller.ExecutedIds);
        Assert.Equal(0, controller.AcknowledgementsSent);
    }

    [Theory]
    [InlineData("<DT><DR><A ID=\"1\"/></DR></DT>")]
    [InlineData("<DT><DR><A ID=\"1\" T=\"99\" V1=\"0\" V2=\"0\" V3=\"0\" V4=\"0\" V5=\"0\" V6=\"0\" V7=\"0\" M=\"\"/></DR></DT>")]
    public async Task Batch_ActionOfNoKnownType_DriverQuitsAndHaltsWithoutAcknowledging(string batch)
    {
        await using var controller = await KukaTestSupport.StartKukaAsync();
        using var client = await KukaTestSupport.ConnectRawAsync(controller.Port);
        await KukaTestSupport.ReadElementAsync(client, new KukaXmlReader());
        await client.GetStream().WriteAsync(Encoding.ASCII.GetBytes(batch));

        // Without T (the EthernetKRL memory is empty, the slot keeps its 0) or with 99, the driver's SWITCH reaches DEFAULT.
        await Eventually.TrueAsync(() => controller.PendantMessages.Contains(Quit("Machina sent an action type this driver does not know; load the driver that matches Machina.")), "the quit message", Timeout);
        Assert.Equal(1, controller.RequestsReceived);
        Assert.Empty(controller.ExecutedIds);
        Assert.Equal(0, controller.AcknowledgementsSent);
    }

    [Fact]
    public async Task Batch_BufferCapacityOne_EveryActionRunsAndIsAcknowledged()
    {
        // The controller holds what the driver holds (its ring), not a queue of its own: a capacity of 1 no longer blocks the
        // channel's reader on the second action while the first waits for the driver, which had not read the document yet
        // (issue 44: the execution loop's bounded buffer deadlocked there).
        await using var controller = await KukaTestSupport.StartKukaAsync(new VirtualKukaControllerOptions { InstantExecution = true, BufferCapacity = 1 });
        using var client = await KukaTestSupport.ConnectRawAsync(controller.Port);
        var reader = new KukaXmlReader();
        await KukaTestSupport.ReadElementAsync(client, reader);
        var sb = new StringBuilder();
        KukaInstruction.AppendBatch(sb, Enumerable.Range(1, 3).Select(id => new KukaInstruction(id, KukaActionCode.Wait, new KukaValues(), "")));
        await client.GetStream().WriteAsync(Encoding.ASCII.GetBytes(sb.ToString()));

        var acknowledged = new List<int>();
        for (int i = 0; i < 3; i++)
        {
            KukaElement ack = await KukaTestSupport.ReadElementAsync(client, reader);
            Assert.Equal("R", ack.Name);
            acknowledged.Add(ack.Integer("ID"));
        }
        Assert.Equal([1, 2, 3], acknowledged);
        Assert.Equal([1, 2, 3], controller.ExecutedIds);
        Assert.Equal((3, 3, 0), (controller.RequestsReceived, controller.RequestsExecuted, controller.BufferedRequestCount));
        Assert.Empty(controller.Errors);
    }

    [Fact]
    public async Task Document_NotInTheChannelsConfiguration_IgnoredAndTheNextBatchRuns()
    {
        await using var controller = await KukaTestSupport.StartKukaAsync();
        using var client = await KukaTestSupport.ConnectRawAsync(controller.Port);
        var reader = new KukaXmlReader();
        await KukaTestSupport.ReadElementAsync(client, reader);
        await client.GetStream().WriteAsync(Encoding.ASCII.GetBytes("<XX/><DT><DR><A ID=\"1\" T=\"7\" V1=\"0\" V2=\"0\" V3=\"0\" V4=\"0\" V5=\"0\" V6=\"0\" V7=\"0\" M=\"\"/></DR></DT>"));

        KukaElement ack = await KukaTestSupport.ReadElementAsync(client, reader);
        Assert.Equal(("R", 1), (ack.Name, ack.Integer("ID")));
        Assert.Equal([1], controller.ExecutedIds);
        Assert.Empty(controller.Errors);
    }
}
