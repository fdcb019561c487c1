using System.Globalization;
using System.Net;
using System.Net.Sockets;
using System.Text;
using Machina.Simulation.Rapid;
using Machina.Simulation.Twin;

namespace Machina.Tests.Simulation.Rapid;

/// <summary>
/// The RAPID twin's network stack holds what a task sends (<see cref="TwinHeldOutbox"/>) and writes it in one write when the task is
/// about to wait, after a bounded number of statements, before SocketClose and when the task's run ends (issue 45: one write
/// per acknowledgement was a third of the virtual ABB's processor time). Before, every SocketSend was its own write.
/// </summary>
public class RapidSocketOutboxTests
{
    private static readonly TimeSpan Wait = TimeSpan.FromSeconds(10);

    [Fact]
    public async Task SocketSend_TwoSendsThenAWait_HeldWhileTheTaskRunsThenOneWrite()
    {
        // Between the sends the task reads the clock, which the test holds: before, "ab" had left by then.
        using var clock = new HeldClock();
        await using var session = await Session.StartAsync("""
            SocketReceive client \Str:=text \Time:=10;
            SocketSend client \Str:="ab";
            text := CTime();
            SocketSend client \Str:="cd";
            SocketReceive client \Str:=text \Time:=10;
            """, clock);
        await session.Client.SendAsync(Encoding.ASCII.GetBytes("go"), SocketFlags.None);
        Assert.True(clock.Inside.Wait(Wait), "the task to read the clock");
        int available = session.Client.Available;
        clock.Release.Set();
        Assert.Equal(0, available);
        var buffer = new byte[16];
        using var timeout = new CancellationTokenSource(Wait);
        int n = await session.Client.ReceiveAsync(buffer, SocketFlags.None, timeout.Token);
        Assert.Equal("abcd", Encoding.ASCII.GetString(buffer, 0, n));
        await session.Client.SendAsync(Encoding.ASCII.GetBytes("end"), SocketFlags.None);
        Assert.Equal(RapidProgramState.Finished, await session.Run.WaitAsync(Wait));
    }

    [Fact]
    public async Task SocketSend_ThenComputingWithoutAWait_ArrivesAfterTheStatementBound()
    {
        await using var session = await Session.StartAsync("""
            SocketSend client \Str:="ab";
            WHILE TRUE DO
              n := n + 1;
            ENDWHILE
            """);
        Assert.Equal("ab", await session.ReadAsync(2));
        Assert.False(session.Run.IsCompleted);
    }

    [Fact]
    public async Task SocketSend_ThenAnError_TheBytesArriveBeforeTheTaskStops()
    {
        await using var session = await Session.StartAsync("""
            SocketSend client \Str:="bye";
            n := 1 / 0;
            """);
        Assert.Equal(RapidProgramState.Failed, await session.Run.WaitAsync(Wait));
        // Written before the task showed failed (loopback delivers within the write): all of it is there now.
        Assert.Equal(3, session.Client.Available);
        Assert.Equal("bye", await session.ReadAsync(3));
    }

    [Fact]
    public async Task SocketClose_WritesWhatIsHeldBeforeItCloses()
    {
        await using var session = await Session.StartAsync("""
            SocketSend client \Str:="last";
            SocketClose client;
            WHILE TRUE DO
              n := n + 1;
            ENDWHILE
            """);
        Assert.Equal("last", await session.ReadAsync(4));
        var buffer = new byte[4];
        using var closed = new CancellationTokenSource(Wait);
        Assert.Equal(0, await session.Client.ReceiveAsync(buffer, SocketFlags.None, closed.Token));
    }

    [Fact]
    public void Outbox_OnTheTasksThread_HoldsUntilFlushedThenWritesOnce()
    {
        using var pair = SocketPair.Open();
        var (sends, outbox) = Owned(pair);
        outbox.Write("ab"u8);
        outbox.Write("cd"u8);
        Assert.True(outbox.Holds);
        Assert.Equal(0, pair.Client.Available);
        Machina.Simulation.Twin.TwinWait.Blocking(); // the task is about to wait
        Assert.False(outbox.Holds);
        Assert.Equal("abcd", pair.ReadAvailable());
    }

    [Fact]
    public void Outbox_StatementBound_WritesWithoutAWait()
    {
        using var pair = SocketPair.Open();
        var (sends, outbox) = Owned(pair);
        outbox.Write("ab"u8);
        for (int i = 1; i < TwinHeldSends.StatementBound; i++)
        {
            sends.Statement();
        }
        Assert.True(outbox.Holds);
        sends.Statement();
        Assert.False(outbox.Holds);
        Assert.Equal("ab", pair.ReadAvailable());
    }

    [Fact]
    public void Outbox_SizeBound_WritesAtOnce()
    {
        using var pair = SocketPair.Open();
        var (sends, outbox) = Owned(pair);
        outbox.Write(new byte[TwinHeldOutbox.SizeBound - 1]);
        Assert.True(outbox.Holds);
        outbox.Write(new byte[1]);
        Assert.False(outbox.Holds);
        sends.Flush();
    }

    [Fact]
    public void Outbox_WriteFromAnotherThread_GoesOutAtOnceAfterWhatIsHeld()
    {
        using var pair = SocketPair.Open();
        var (sends, outbox) = Owned(pair);
        outbox.Write("ab"u8);
        // A thread of its own: a pool thread could be this very thread again (an awaited Task.Run ran there once in CI).
        var other = new Thread(() => outbox.Write("cd"u8));
        other.Start();
        Assert.True(other.Join(TimeSpan.FromSeconds(10)));
        Assert.False(outbox.Holds);
        Assert.Equal("abcd", pair.ReadAvailable());
        sends.Flush();
    }

    [Fact]
    public void Outbox_AfterTheRunEnded_NoThreadIsHeld()
    {
        // The run's end disowns the list: a later thread with the same managed id (ids are reused) never waits in a twin's wait,
        // so what it writes must go out at once.
        using var pair = SocketPair.Open();
        var (sends, outbox) = Owned(pair);
        outbox.Write("ab"u8);
        Assert.True(outbox.Holds);
        sends.Flush();
        sends.Disown();
        outbox.Write("cd"u8);
        Assert.False(outbox.Holds);
        Assert.Equal("abcd", ReadExactly(pair, 4));
    }

    [Fact]
    public void Flush_OfAnotherThreadsList_LeavesThisThreadsHeldBytesToGoAtItsWait()
    {
        // This thread owns one list and holds bytes in it; it also flushes a list another thread owns (as a stop or an EKI_Close
        // does). Its own bytes must still go out when it is about to block: before, that flush cleared this thread's hook.
        using var mine = SocketPair.Open();
        using var theirs = SocketPair.Open();
        var (sends, outbox) = Owned(mine);
        TwinHeldSends? other = null;
        var owner = new Thread(() =>
        {
            (other, TwinHeldOutbox held) = Owned(theirs);
            held.Write("xy"u8);
        });
        owner.Start();
        Assert.True(owner.Join(TimeSpan.FromSeconds(10)));
        outbox.Write("ab"u8);
        other!.Flush();
        Assert.Equal("xy", ReadExactly(theirs, 2));
        Assert.True(outbox.Holds);
        TwinWait.Blocking();
        Assert.False(outbox.Holds);
        Assert.Equal("ab", ReadExactly(mine, 2));
        sends.Flush();
    }

    [Fact]
    public void Outbox_WriteThatFailed_TheNextWriteSaysClosed()
    {
        using var pair = SocketPair.Open();
        var (sends, outbox) = Owned(pair);
        outbox.Write("ab"u8);
        pair.Server.Dispose(); // the connection broke under the held bytes
        sends.Flush();
        Assert.Throws<IOException>(() => outbox.Write("cd"u8));
    }

    /// <summary>A RAPID program that accepts one client, runs <c>body</c> and ends; the test's client connected to it.</summary>
    private sealed class Session : IAsyncDisposable
    {
        private readonly CancellationTokenSource _stop = new(TimeSpan.FromSeconds(60));
        private readonly TcpListener _listener;

        private Session(TcpListener listener, Socket client, Task<RapidProgramState> run) => (_listener, Client, Run) = (listener, client, run);

        public Socket Client { get; }

        public Task<RapidProgramState> Run { get; private set; }

        public static async Task<Session> StartAsync(string body, HeldClock? clock = null)
        {
            var listener = new TcpListener(IPAddress.Loopback, 0);
            listener.Start();
            int port = ((IPEndPoint)listener.LocalEndpoint).Port;
            var twin = new RapidTwinController(new RapidTwinOptions { Time = clock ?? TimeProvider.System });
            twin.Reserve(listener);
            twin.Load(("T.mod", $$"""
                MODULE T
                VAR socketdev server;
                VAR socketdev client;
                VAR string text;
                VAR num n;
                PROC main()
                  SocketCreate server;
                  SocketBind server, "127.0.0.1", {{port.ToString(CultureInfo.InvariantCulture)}};
                  SocketListen server;
                  SocketAccept server, client \Time:=10;
                {{body}}
                ENDPROC
                ENDMODULE
                """));
            var session = new Session(listener, new Socket(AddressFamily.InterNetwork, SocketType.Stream, ProtocolType.Tcp), Task.FromResult(RapidProgramState.Ready));
            session.Run = Task.Run(() =>
            {
                clock?.Hold(Environment.CurrentManagedThreadId);
                return twin.Run("main", session._stop.Token);
            });
            using var connect = new CancellationTokenSource(Wait);
            await session.Client.ConnectAsync(IPAddress.Loopback, port, connect.Token);
            return session;
        }

        /// <summary>Reads exactly <paramref name="count"/> bytes (bounded wait).</summary>
        public async Task<string> ReadAsync(int count)
        {
            var buffer = new byte[count];
            int read = 0;
            using var timeout = new CancellationTokenSource(Wait);
            while (read < count)
            {
                int n = await Client.ReceiveAsync(buffer.AsMemory(read), SocketFlags.None, timeout.Token);
                Assert.NotEqual(0, n);
                read += n;
            }
            return Encoding.ASCII.GetString(buffer);
        }

        public async ValueTask DisposeAsync()
        {
            await _stop.CancelAsync();
            Client.Dispose();
            await Task.WhenAny(Run, Task.Delay(Wait));
            _listener.Stop();
            _stop.Dispose();
        }
    }

    /// <summary>The system clock, except that the first reading of the program's thread waits until the test releases it.</summary>
    private sealed class HeldClock : TimeProvider, IDisposable
    {
        private int _thread = -1;

        public ManualResetEventSlim Inside { get; } = new();

        public ManualResetEventSlim Release { get; } = new();

        public void Hold(int thread) => Volatile.Write(ref _thread, thread);

        public override DateTimeOffset GetUtcNow()
        {
            if (Environment.CurrentManagedThreadId == Volatile.Read(ref _thread) && !Inside.IsSet)
            {
                Inside.Set();
                Release.Wait(Wait);
            }
            return base.GetUtcNow();
        }

        public void Dispose()
        {
            Inside.Dispose();
            Release.Dispose();
        }
    }

    /// <summary>Two connected loopback sockets.</summary>
    /// <summary>A held list owned by the calling thread (it stands for the task that accepted the connection) and its outbox on <paramref name="pair"/>.</summary>
    private static (TwinHeldSends Sends, TwinHeldOutbox Outbox) Owned(SocketPair pair)
    {
        var sends = new TwinHeldSends();
        sends.Own();
        return (sends, new TwinHeldOutbox(pair.Server, sends));
    }

    /// <summary>Reads <paramref name="count"/> bytes from the client side (at most 10 s), as text.</summary>
    private static string ReadExactly(SocketPair pair, int count)
    {
        pair.Client.ReceiveTimeout = 10_000;
        var buffer = new byte[count];
        int got = 0;
        while (got < count && pair.Client.Receive(buffer, got, count - got, SocketFlags.None) is > 0 and var n)
        {
            got += n;
        }
        return Encoding.ASCII.GetString(buffer, 0, got);
    }

    private sealed class SocketPair : IDisposable
    {
        private SocketPair(Socket server, Socket client) => (Server, Client) = (server, client);

        public Socket Server { get; }

        public Socket Client { get; }

        public static SocketPair Open()
        {
            using var listener = new Socket(AddressFamily.InterNetwork, SocketType.Stream, ProtocolType.Tcp);
            listener.Bind(new IPEndPoint(IPAddress.Loopback, 0));
            listener.Listen(1);
            var client = new Socket(AddressFamily.InterNetwork, SocketType.Stream, ProtocolType.Tcp);
            client.Connect(listener.LocalEndPoint!);
            return new SocketPair(listener.Accept(), client);
        }

        /// <summary>What arrived so far (loopback delivers within the sender's write).</summary>
        public string ReadAvailable()
        {
            var buffer = new byte[Math.Max(1, Client.Available)];
            int n = Client.Available > 0 ? Client.Receive(buffer) : 0;
            return Encoding.ASCII.GetString(buffer, 0, n);
        }

        public void Dispose()
        {
            Server.Dispose();
            Client.Dispose();
        }
    }
}
