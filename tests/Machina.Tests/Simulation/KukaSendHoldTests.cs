using System.Text;
using Machina.Simulation;
using Machina.Tests.Online;

namespace Machina.Tests.Simulation;

/// <summary>
/// The virtual KUKA's driver connection writes through the EthernetKRL stack's outbox (<c>TwinHeldOutbox</c>): what the driver's
/// EKI_Send writes while the robot interpreter runs is held and goes out when the interpreter is about to wait (issue 45). Every
/// acknowledgement still arrives, in order, each executed and counted on its own; none is left behind at the driver's wait.
/// How many reads they take depends on when the twin's reader hands the interpreter each action, so that is measured by the
/// benchmark (system calls per action), not asserted here.
/// </summary>
public class KukaSendHoldTests
{
    private static readonly TimeSpan Timeout = TimeSpan.FromSeconds(10);

    [Theory]
    [InlineData(1)]
    [InlineData(20)]
    public async Task ActionsRunInARow_EveryAcknowledgementArrivesInOrder_TheLastOneAtTheDriversWait(int count)
    {
        await using var controller = await KukaTestSupport.StartKukaAsync(new VirtualKukaControllerOptions { InstantExecution = true });
        using var client = await KukaTestSupport.ConnectRawAsync(controller.Port);
        await KukaTestSupport.ReadElementAsync(client, new KukaXmlReader()); // the state, let go at the driver's first WAIT FOR
        var batch = new StringBuilder();
        KukaInstruction.AppendBatch(batch, Enumerable.Range(1, count).Select(id => new KukaInstruction(id, KukaActionCode.Precision, new KukaValues(), "")));
        await client.GetStream().WriteAsync(Encoding.ASCII.GetBytes(batch.ToString()));

        // The driver then waits for the next action: held acknowledgements that did not go out there would never arrive.
        string expected = string.Concat(Enumerable.Range(1, count).Select(id => $"<R ID=\"{id}\" />"));
        var received = new StringBuilder();
        byte[] buffer = new byte[8192];
        using var stop = new CancellationTokenSource(Timeout);
        while (received.Length < expected.Length)
        {
            int read = await client.GetStream().ReadAsync(buffer, stop.Token);
            Assert.True(read > 0, "the twin closed the connection");
            received.Append(Encoding.ASCII.GetString(buffer, 0, read));
        }

        Assert.Equal(expected, received.ToString());
        Assert.Equal(Enumerable.Range(1, count), controller.ExecutedIds);
        Assert.Equal(count, controller.AcknowledgementsSent);
    }
}
