using System.Globalization;
using System.Text;
using Machina.Simulation;
using Machina.Tests.Online;
using Machina.Tests.Support;

namespace Machina.Tests.Stopping;

/// <summary>
/// A stop when the driver runs no action (issue 44): its interrupt has nothing to fail, so it sends only <c>&lt;C K="3"/&gt;</c>,
/// and it still empties its ring. The virtual KUKA drops what the driver held as the stop's <c>F</c> would have it: counted
/// lost, none of it left waiting nor ever logged executed.
/// </summary>
public class KukaStopNothingRunningTests
{
    [Fact]
    public async Task StopWhilePausedBetweenActions_OnlyItsAnswer_TheHeldActionsAreDroppedAndCountedLost()
    {
        await using var controller = await KukaTestSupport.StartKukaAsync();
        using var client = await KukaTestSupport.ConnectRawAsync(controller.Port);
        var reader = new KukaXmlReader();
        Assert.Equal("S", (await KukaTestSupport.ReadElementAsync(client, reader)).Name);

        // Paused in the main loop (no action runs): the actions that arrive stay in the channel's memory, held.
        await WriteAsync(client, "<PAUSE/>");
        KukaElement paused = await KukaTestSupport.ReadElementAsync(client, reader);
        Assert.Equal(("C", "1"), (paused.Name, paused.Attribute("K")));
        await WriteAsync(client, "<DT><DR>" + Action(1) + Action(2) + Action(3) + "</DR></DT>");
        await Eventually.TrueAsync(() => controller.BufferedRequestCount == 3, "the three actions held", TimeSpan.FromSeconds(10));

        await WriteAsync(client, "<STOP/>");
        KukaElement stopped = await KukaTestSupport.ReadElementAsync(client, reader);

        Assert.Equal(("C", "3"), (stopped.Name, stopped.Attribute("K")));
        await Eventually.TrueAsync(() => controller.BufferedRequestCount == 0, "the held actions dropped", TimeSpan.FromSeconds(10));
        Assert.Equal(3, controller.RequestsLost);
        Assert.Empty(controller.ExecutedIds);
        Assert.Contains("stopped by the host (Robot.Stop): 3 requests received and not executed are dropped", controller.PendantMessages);
    }

    private static async Task WriteAsync(System.Net.Sockets.TcpClient client, string text) =>
        await client.GetStream().WriteAsync(Encoding.ASCII.GetBytes(text));

    /// <summary>A small joint move (type 3) to A2 -85 + id degrees.</summary>
    private static string Action(int id) => string.Create(CultureInfo.InvariantCulture,
        $"<A ID=\"{id}\" T=\"3\" V1=\"0\" V2=\"{-85 + id}\" V3=\"90\" V4=\"0\" V5=\"90\" V6=\"0\" V7=\"0\" M=\"\"/>");
}
