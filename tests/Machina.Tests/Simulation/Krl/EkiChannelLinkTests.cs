using System.Net;
using System.Net.Sockets;
using Machina.Simulation.Krl;
using static Machina.Tests.Online.OnlineTestSupport;

namespace Machina.Tests.Simulation.Krl;

/// <summary>
/// An EthernetKRL channel's ALIVE flag follows its connection, also when the program clears the channel while the connection's
/// reader is ending it. Before, EKI_Clear (and the virtual KUKA's program reset) returned while a reader that had begun the
/// disconnection had not yet put $FLAG[1] down; its late write then hid the next channel's client from the driver, which never
/// greeted it and never listened again (CI, session 16: 20 reconnections "did not send its state within 15 s").
/// </summary>
public class EkiChannelLinkTests
{
    private const string Channel = "machina_kuka_server";

    private const string OpenProgram = """
        DEF link_open( )
          DECL EKI_STATUS ret
          ret = EKI_Init("machina_kuka_server")
          ret = EKI_Open("machina_kuka_server")
        END
        """;

    [Fact]
    public async Task Clear_WhileTheReaderEndsTheConnection_ReturnsWithTheAliveFlagDown_AndTheNextClientIsSeen()
    {
        var seam = new ClosingSeam();
        using var twin = new KrlTwinController(new KrlTwinOptions { Seam = seam });
        seam.Clear = () =>
        {
            twin.ClearEki(Channel);
            return Alive(twin);
        };
        var listener = new TcpListener(IPAddress.Loopback, 0);
        listener.Start();
        try
        {
            twin.Reserve(Channel, listener);
            twin.AddEkiConfiguration(Channel, Machina.KukaDriverModules.Read(Channel + ".xml")
                .Replace("{{HOSTNAME}}", "127.0.0.1", StringComparison.Ordinal).Replace("{{PORT}}", "0", StringComparison.Ordinal));
            twin.Load(("link_open.src", OpenProgram));
            int port = ((IPEndPoint)listener.LocalEndpoint).Port;
            Assert.Equal(KrlProgramState.Finished, twin.Run("link_open"));
            using (var first = new TcpClient())
            {
                await first.ConnectAsync(IPAddress.Loopback, port);
                await EventuallyAsync(() => Alive(twin), "the first client's flag");
            }

            // The first client left: its reader is in the seam's Closed, its flag not down yet, when the program clears the
            // channel (as a program reset does) and looks at $FLAG[1] once EKI_Clear returned.
            bool flagAfterClear = await seam.Cleared.Task.WaitAsync(Limit);
            Assert.False(flagAfterClear, "EKI_Clear returned while the cleared channel's connection still held $FLAG[1] up");

            // The program opens the channel again; the next client is seen, and no late write of the old channel hides it.
            Assert.Equal(KrlProgramState.Finished, twin.Run("link_open"));
            using var second = new TcpClient();
            await second.ConnectAsync(IPAddress.Loopback, port);
            await EventuallyAsync(() => twin.EkiConnected(Channel), "the second client to be attached");
            Assert.True(Alive(twin), "$FLAG[1] is down while the second client is connected");
            Assert.Equal(1, seam.ClosedCount);
        }
        finally
        {
            listener.Stop();
        }
    }

    [Fact]
    public async Task Clear_BetweenADocumentsStoreAndItsFlag_LeavesTheFlagDown()
    {
        // The program clears the channel (as a program reset does) after the reader stored a document and before it set the
        // document's flag ($FLAG[2] of DT): the cleared channel let the document go, and its flag must not come up after
        // EKI_Clear returned. The seam clears on the reader's own thread at the point between the two (the link's lock is
        // re-entrant), which makes the order certain instead of a race.
        var seam = new ClearingSeam();
        using var twin = new KrlTwinController(new KrlTwinOptions { Seam = seam });
        seam.Clear = () => twin.ClearEki(Channel);
        var listener = new TcpListener(IPAddress.Loopback, 0);
        listener.Start();
        try
        {
            twin.Reserve(Channel, listener);
            twin.AddEkiConfiguration(Channel, Machina.KukaDriverModules.Read(Channel + ".xml")
                .Replace("{{HOSTNAME}}", "127.0.0.1", StringComparison.Ordinal).Replace("{{PORT}}", "0", StringComparison.Ordinal));
            twin.Load(("link_open.src", OpenProgram));
            int port = ((IPEndPoint)listener.LocalEndpoint).Port;
            Assert.Equal(KrlProgramState.Finished, twin.Run("link_open"));
            using var client = new TcpClient();
            await client.ConnectAsync(IPAddress.Loopback, port);
            await EventuallyAsync(() => Alive(twin), "the client's flag");
            await client.GetStream().WriteAsync("<DT><DR><A ID=\"7\" T=\"1\"/></DR></DT>"u8.ToArray());

            Thread reader = await seam.Reader.Task.WaitAsync(Limit);
            Assert.True(reader.Join(Limit), "the cleared connection's reader did not end");
            Assert.Equal(1, seam.ReceivedCount);
            Assert.False(Flag(twin, 2), "$FLAG[2] came up for a document of a channel the program had cleared");
            Assert.False(Alive(twin), "$FLAG[1] is up after the channel was cleared");
            Assert.False(twin.EkiConnected(Channel));
        }
        finally
        {
            listener.Stop();
        }
    }

    private static bool Flag(KrlTwinController twin, int number) => (bool)((KrlArrayValue)twin.Environment.System["$FLAG"].Value)[number - 1];

    private static bool Alive(KrlTwinController twin) => (bool)((KrlArrayValue)twin.Environment.System["$FLAG"].Value)[0];

    /// <summary>
    /// Lets the program clear the channel (on a thread of its own) while the first connection's reader is in Closed, and gives
    /// the clear a second to finish there, as a reader preempted at that point would.
    /// </summary>
    private sealed class ClosingSeam : IEkiSeam
    {
        private int _closed;

        public Func<bool>? Clear { get; set; }

        public TaskCompletionSource<bool> Cleared { get; } = new(TaskCreationOptions.RunContinuationsAsynchronously);

        public int ClosedCount => Volatile.Read(ref _closed);

        public bool Accepted(EkiChannel channel, TcpClient client) => true;

        public void Received(EkiChannel channel, ReadOnlySpan<(string Tag, string Value)> values)
        {
        }

        public bool Send(EkiChannel channel, string root, byte[] document) => channel.SendDirect(document);

        public void Closed(EkiChannel channel, TcpClient client)
        {
            if (Interlocked.Increment(ref _closed) != 1)
            {
                return;
            }
            var clear = Task.Run(() => Cleared.TrySetResult(Clear!()));
            // Only how long a clear that does not wait for this reader has to show it: a clear that waits ends after this returns.
            clear.Wait(TimeSpan.FromSeconds(1));
        }
    }

    /// <summary>Clears the channel from inside the first document's Received, on the reader's thread, and tells which thread that was.</summary>
    private sealed class ClearingSeam : IEkiSeam
    {
        private int _received;

        public Action? Clear { get; set; }

        public TaskCompletionSource<Thread> Reader { get; } = new(TaskCreationOptions.RunContinuationsAsynchronously);

        public int ReceivedCount => Volatile.Read(ref _received);

        public bool Accepted(EkiChannel channel, TcpClient client) => true;

        public void Received(EkiChannel channel, ReadOnlySpan<(string Tag, string Value)> values)
        {
            if (Interlocked.Increment(ref _received) == 1)
            {
                Clear!();
                Reader.TrySetResult(Thread.CurrentThread);
            }
        }

        public bool Send(EkiChannel channel, string root, byte[] document) => channel.SendDirect(document);

        public void Closed(EkiChannel channel, TcpClient client)
        {
        }
    }
}
