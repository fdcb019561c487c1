using System.Net;
using System.Net.Sockets;
using System.Text;
using Machina.Simulation;
using Machina.Tests.Online;

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
        Assert.Equal(KukaMessages.State(new Joints(0, -90, 90, 0, 90, 0), flange.Position, flange.Rotation, 0, 0), state.ToString().Replace("/>", "></S>", StringComparison.Ordinal));
        Assert.Equal(new DeviceProgress(0, 0), KukaState.Parse(state).Progress);
    }

    [Fact]
    public async Task Batch_MoreActionsThanTheRingHolds_RefusedAndTheClientDropped()
    {
        await using var controller = await KukaTestSupport.StartKukaAsync();
        controller.StopAnswering();
        using var client = await KukaTestSupport.ConnectRawAsync(controller.Port);
        await KukaTestSupport.ReadElementAsync(client, new KukaXmlReader());
        var sb = new StringBuilder();
        KukaInstruction.AppendBatch(sb, Enumerable.Range(1, KukaProtocol.Capacity + 1).Select(id => new KukaInstruction(id, KukaActionCode.Wait, new KukaValues(), "")));
        await client.GetStream().WriteAsync(Encoding.ASCII.GetBytes(sb.ToString()));

        using var cts = new CancellationTokenSource(Timeout);
        Assert.Equal(0, await client.GetStream().ReadAsync(new byte[16], cts.Token));
        Assert.Equal(KukaProtocol.Capacity, controller.RequestsReceived);
        Assert.Contains($"the host sent action {KukaProtocol.Capacity + 1} while the {KukaProtocol.Capacity} slots of the ring hold actions not executed", Assert.Single(controller.Errors), StringComparison.Ordinal);
    }

    [Theory]
    [InlineData("<DT><DR><A ID=\"1\"/></DR></DT>", "has no attribute")]
    [InlineData("<XX/>", "expected a batch")]
    [InlineData("<DT><DR><A ID=\"1\" T=\"99\" V1=\"0\" V2=\"0\" V3=\"0\" V4=\"0\" V5=\"0\" V6=\"0\" V7=\"0\" M=\"\"/></DR></DT>", "T=\"99\"")]
    public async Task Batch_Malformed_ErrorKeptAndClientDropped(string batch, string expected)
    {
        await using var controller = await KukaTestSupport.StartKukaAsync();
        using var client = await KukaTestSupport.ConnectRawAsync(controller.Port);
        await KukaTestSupport.ReadElementAsync(client, new KukaXmlReader());
        await client.GetStream().WriteAsync(Encoding.ASCII.GetBytes(batch));

        using var cts = new CancellationTokenSource(Timeout);
        Assert.Equal(0, await client.GetStream().ReadAsync(new byte[16], cts.Token));
        Assert.Contains(expected, Assert.Single(controller.Errors), StringComparison.Ordinal);
        Assert.Equal(0, controller.RequestsReceived);
    }
}
