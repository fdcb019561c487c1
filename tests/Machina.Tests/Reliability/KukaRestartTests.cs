using System.Globalization;
using System.Net.Sockets;
using System.Text;
using Machina.Simulation;
using Machina.Simulation.Krl;
using Machina.Tests.Online;
using Machina.Tests.Support;

namespace Machina.Tests.Reliability;

/// <summary>
/// The virtual KUKA's restart that loses the progress (issue 40), spoken to on the wire so that its timing is the test's: the
/// link breaks after an acknowledgement, the KRL driver goes on with the actions of its ring with nobody connected (their
/// acknowledgements are not sent), and the next connection restarts the controller. The controller's buffer had already
/// dropped those actions, and the restart waited for it to log them: the driver never started again and every later
/// connection waited for a state that never came (1 restart trial in 15 hung that way).
/// </summary>
public class KukaRestartTests
{
    private const int Actions = 10;
    private static readonly TimeSpan Wait = TimeSpan.FromSeconds(10);

    [Fact]
    public async Task RestartLosingProgress_AfterTheDriverRanHeldActionsAlone_ItComesBackAndLogsEachOnce()
    {
        // The fault strikes at the 2nd acknowledgement with 8 actions held, and this seed lets all 8 run before the restart,
        // so the restart can only come from the next connection (the driver acknowledges nothing with nobody connected).
        int seed = Enumerable.Range(1, 1000).First(s => new Random(s).Next(Actions - 2 + 1) == Actions - 2);
        await using var controller = await KukaTestSupport.StartKukaAsync(new VirtualKukaControllerOptions
        {
            Faults = new VirtualFaults { After = 2, Kinds = [VirtualFault.RestartLosingProgress], Seed = seed },
        });
        using (TcpClient first = await KukaTestSupport.ConnectRawAsync(controller.Port))
        {
            var reader = new KukaXmlReader();
            await KukaTestSupport.ReadElementAsync(first, reader);
            await first.GetStream().WriteAsync(Encoding.ASCII.GetBytes(WaitBatch(0.3)));
            KukaElement ack = await KukaTestSupport.ReadElementAsync(first, reader);
            Assert.Equal(("R", 1), (ack.Name, ack.Integer("ID")));
            Assert.Equal(0, await ReadToEndAsync(first)); // the 2nd acknowledgement never leaves: the link breaks
        }
        string broke = $"fault: the link broke; {Actions - 2} of the {Actions - 2} requests held run before the restart, unacknowledged";
        await Eventually.TrueAsync(() => controller.PendantMessages.Contains(broke), broke, Wait); // written just after the link broke
        KrlModule driver = controller.Twin!.Modules["machina_kuka_driver"];
        await Eventually.TrueAsync(() => KrlValues.ToInt(driver.Data["last_executed"].Value) >= 6, "the driver running actions 3 to 6 alone", Wait);

        using (TcpClient refused = await KukaTestSupport.ConnectRawAsync(controller.Port))
        {
            Assert.Equal(0, await ReadToEndAsync(refused)); // refused: the controller restarts now
        }
        Assert.Contains("connection refused: the controller is restarting", controller.PendantMessages);

        // The program that starts again greets the next client (one that came while the old program's channel was still open is
        // closed with it, and connects again, as a host does).
        KukaElement state = await GreetingAsync(controller.Port);
        Assert.Equal(new DeviceProgress(0, 0), KukaState.Parse(state).Progress);
        Assert.Contains("program reset: machina_kuka_driver starts again from the top", controller.PendantMessages);

        // What ran is in the execution log once each, in order (those run alone too), the rest was lost; nothing was acknowledged after 1.
        IReadOnlyList<int> ran = controller.ExecutedIds;
        Assert.True(ran.Count >= 6, $"the log holds {string.Join(' ', ran)}");
        Assert.Equal(Enumerable.Range(1, ran.Count), ran);
        Assert.Equal(ran.Count, controller.RequestsExecuted);
        Assert.Equal(Actions - ran.Count, controller.RequestsLost);
        Assert.Equal(1, controller.AcknowledgementsSent);
        Assert.Empty(controller.Errors);
    }

    /// <summary>The state the driver greets a connection with, connecting again while it is closed without one (at most 20 times).</summary>
    private static async Task<KukaElement> GreetingAsync(int port)
    {
        for (int attempt = 1; ; attempt++)
        {
            using TcpClient client = await KukaTestSupport.ConnectRawAsync(port);
            var reader = new KukaXmlReader();
            var bytes = new byte[4096];
            using var cts = new CancellationTokenSource(Wait);
            try
            {
                int n;
                while ((n = await client.GetStream().ReadAsync(bytes, cts.Token)) > 0)
                {
                    reader.Append(bytes.AsSpan(0, n));
                    if (reader.TryRead(out KukaElement element))
                    {
                        return element;
                    }
                }
            }
            catch (IOException)
            {
                // Reset: closed too.
            }
            Assert.True(attempt < 20, "the driver closed 20 connections in a row without its state");
            await Task.Delay(50);
        }
    }

    /// <summary>A batch of <see cref="Actions"/> waits of <paramref name="seconds"/> (type 7, WAIT SEC), ids 1 on.</summary>
    private static string WaitBatch(double seconds)
    {
        var sb = new StringBuilder("<DT><DR>");
        for (int id = 1; id <= Actions; id++)
        {
            sb.Append(CultureInfo.InvariantCulture, $"<A ID=\"{id}\" T=\"7\" V1=\"{seconds}\" V2=\"0\" V3=\"0\" V4=\"0\" V5=\"0\" V6=\"0\" V7=\"0\" M=\"\"/>");
        }
        return sb.Append("</DR></DT>").ToString();
    }

    /// <summary>Reads until the controller closes the connection (bounded): the bytes read, 0 when it closed without a word.</summary>
    private static async Task<int> ReadToEndAsync(TcpClient client)
    {
        using var cts = new CancellationTokenSource(Wait);
        var buffer = new byte[4096];
        int total = 0;
        try
        {
            int n;
            while ((n = await client.GetStream().ReadAsync(buffer, cts.Token)) > 0)
            {
                total += n;
            }
        }
        catch (IOException)
        {
            // Reset by the controller: closed too.
        }
        return total;
    }
}
