using System.Text;
using Machina.Simulation;
using Machina.Tests.Online;
using Machina.Tests.Support;

namespace Machina.Tests.Simulation;

/// <summary>
/// The virtual KUKA's log of received actions, which its EthernetKRL seam writes from each document's values: one text per
/// action (several in one document are split at each ID), each attribute named as the host wrote it, a value's &amp;, &lt;, &gt;
/// and " written as XML's entities again, and anything else (an apostrophe, numbers) as received.
/// </summary>
public class EkiSeamReceivedLogTests
{
    [Fact]
    public async Task ActionsHeldWhilePaused_AreLoggedOneTextEach_WithTheirValuesEscapedAsXml()
    {
        await using var controller = await KukaTestSupport.StartKukaAsync();
        using var client = await KukaTestSupport.ConnectRawAsync(controller.Port);
        var reader = new KukaXmlReader();
        Assert.Equal("S", (await KukaTestSupport.ReadElementAsync(client, reader)).Name);
        await WriteAsync(client, "<PAUSE/>");
        KukaElement paused = await KukaTestSupport.ReadElementAsync(client, reader);
        Assert.Equal(("C", "1"), (paused.Name, paused.Attribute("K")));

        // Two actions in one document, then one in a document of its own (its message spells the four escaped characters).
        await WriteAsync(client, "<DT><DR>" + Action(1, "") + Action(2, "x") + "</DR></DT>");
        await WriteAsync(client, "<DT><DR>" + Action(3, "a &amp; &lt;b&gt; &quot;c&quot; 'd' &apos;e&apos;") + "</DR></DT>");
        await Eventually.TrueAsync(() => controller.BufferedRequestCount == 3, "the three actions held", TimeSpan.FromSeconds(10));

        Assert.Equal(
        [
            "<A ID=\"1\" T=\"3\" V1=\"0\" V2=\"-84\" V3=\"90.5\" V4=\"0\" V5=\"90\" V6=\"0\" V7=\"0\" M=\"\"/>",
            "<A ID=\"2\" T=\"3\" V1=\"0\" V2=\"-83\" V3=\"90.5\" V4=\"0\" V5=\"90\" V6=\"0\" V7=\"0\" M=\"x\"/>",
            "<A ID=\"3\" T=\"3\" V1=\"0\" V2=\"-82\" V3=\"90.5\" V4=\"0\" V5=\"90\" V6=\"0\" V7=\"0\" M=\"a &amp; &lt;b&gt; &quot;c&quot; 'd' 'e'\"/>",
        ], controller.ReceivedRequests);
    }

    [Fact]
    public async Task TheLogReadSinceACount_GivesTheSameTextsAsTheWholeLog_AndEachTextIsWrittenOnce()
    {
        await using var controller = await KukaTestSupport.StartKukaAsync();
        using var client = await KukaTestSupport.ConnectRawAsync(controller.Port);
        var reader = new KukaXmlReader();
        Assert.Equal("S", (await KukaTestSupport.ReadElementAsync(client, reader)).Name);
        await WriteAsync(client, "<PAUSE/>");
        Assert.Equal("C", (await KukaTestSupport.ReadElementAsync(client, reader)).Name);

        await WriteAsync(client, "<DT><DR>" + Action(1, "") + Action(2, "&lt;") + "</DR></DT>");
        await Eventually.TrueAsync(() => controller.BufferedRequestCount == 2, "the two actions held", TimeSpan.FromSeconds(10));
        var since = new List<string>();
        Assert.Equal(2, controller.ReceivedRequestsSince(1, since));
        Assert.Equal(["<A ID=\"2\" T=\"3\" V1=\"0\" V2=\"-83\" V3=\"90.5\" V4=\"0\" V5=\"90\" V6=\"0\" V7=\"0\" M=\"&lt;\"/>"], since);

        await WriteAsync(client, "<DT><DR>" + Action(3, "") + "</DR></DT>");
        await Eventually.TrueAsync(() => controller.BufferedRequestCount == 3, "the three actions held", TimeSpan.FromSeconds(10));
        since.Clear();
        Assert.Equal(3, controller.ReceivedRequestsSince(0, since));
        IReadOnlyList<string> whole = controller.ReceivedRequests;
        Assert.Equal(
        [
            "<A ID=\"1\" T=\"3\" V1=\"0\" V2=\"-84\" V3=\"90.5\" V4=\"0\" V5=\"90\" V6=\"0\" V7=\"0\" M=\"\"/>",
            "<A ID=\"2\" T=\"3\" V1=\"0\" V2=\"-83\" V3=\"90.5\" V4=\"0\" V5=\"90\" V6=\"0\" V7=\"0\" M=\"&lt;\"/>",
            "<A ID=\"3\" T=\"3\" V1=\"0\" V2=\"-82\" V3=\"90.5\" V4=\"0\" V5=\"90\" V6=\"0\" V7=\"0\" M=\"\"/>",
        ], whole);
        Assert.Equal(whole, since);
        for (int i = 0; i < 3; i++)
        {
            Assert.Same(whole[i], since[i]); // written at the first read, kept as that text
        }
        since.Clear();
        Assert.Equal(3, controller.ReceivedRequestsSince(3, since));
        Assert.Empty(since);
    }

    private static async Task WriteAsync(System.Net.Sockets.TcpClient client, string text) =>
        await client.GetStream().WriteAsync(Encoding.ASCII.GetBytes(text));

    /// <summary>A small joint move (type 3) to A2 -85 + id degrees, with message <paramref name="message"/> (as XML text).</summary>
    private static string Action(int id, string message) =>
        $"<A ID=\"{id}\" T=\"3\" V1=\"0\" V2=\"{-85 + id}\" V3=\"90.5\" V4=\"0\" V5=\"90\" V6=\"0\" V7=\"0\" M=\"{message}\"/>";
}
