using System.Net;
using System.Net.Sockets;
using System.Runtime.ExceptionServices;
using Machina.Simulation.Rapid;
using Machina.Simulation.Twin;

namespace Machina.Tests.Simulation.Rapid;

/// <summary>
/// A connection the other end closed or reset: the RAPID twin's SocketSend raises ERR_SOCK_CLOSED as before, and the network stack under it
/// throws nothing on the way. Before, each disconnect of the virtual ABB's monitor threw three .NET exceptions before its RAPID
/// error (the held bytes' send: a broken pipe or a reset; the next write's <see cref="IOException"/>; the seam's
/// <see cref="SocketException"/> made to carry the message): caught at once, but paid, with their code compiled, per disconnect.
/// </summary>
public class RapidSocketResetTests
{
    /// <summary>Marks the exceptions of this test's own threads (the twin's task threads inherit it with the execution context).</summary>
    private static readonly AsyncLocal<string?> Owner = new();

    [Fact]
    public void SocketSend_AfterTheClientClosed_RaisesErrSockClosed_WithNoOtherException()
    {
        using var listener = new TcpListener(IPAddress.Loopback, 0);
        listener.Start();
        int port = ((IPEndPoint)listener.LocalEndpoint).Port;
        var twin = new RapidTwinController();
        twin.Reserve(listener);
        twin.Load(("S.mod", $$"""
            MODULE S
              VAR socketdev server;
              VAR socketdev client;
              VAR string text;
              VAR num n;
              PROC main()
                SocketCreate server;
                SocketBind server, "127.0.0.1", {{port}};
                SocketListen server;
                SocketAccept server, client \Time:=WAIT_MAX;
                SocketReceive client \Str:=text \Time:=10;
                SocketSend client \Str:="ok";
                SocketReceive client \Str:=text \Time:=10;
              ERROR
                IF ERRNO = ERR_SOCK_CLOSED THEN
                  TPWrite "closed at " \Num:=n;
                  WHILE n < 1000000 DO
                    n := n + 1;
                    SocketSend client \Str:="x";
                  ENDWHILE
                  TPWrite "never closed";
                ENDIF
              ENDPROC
            ENDMODULE
            """));
        string me = Guid.NewGuid().ToString("N");
        Owner.Value = me;
        var thrown = new List<string>();
        void Record(object? sender, FirstChanceExceptionEventArgs e)
        {
            if (Owner.Value == me)
            {
                lock (thrown)
                {
                    thrown.Add(e.Exception.GetType().Name);
                }
            }
        }

        AppDomain.CurrentDomain.FirstChanceException += Record;
        bool joined;
        try
        {
            twin.StartTasks();
            using var client = new TcpClient();
            client.Connect(IPAddress.Loopback, port);
            NetworkStream stream = client.GetStream();
            stream.ReadTimeout = 10_000;
            stream.Write("go"u8);
            var ok = new byte[2];
            stream.ReadExactly(ok);
            client.Client.Close(); // the twin's receive finds it closed; of its sends after, the first draws a reset, the next fail
            joined = twin.StopTasksWhenEnded(TimeSpan.FromSeconds(20));
        }
        finally
        {
            AppDomain.CurrentDomain.FirstChanceException -= Record;
        }

        Assert.True(joined);
        // The receive's ERR_SOCK_CLOSED, then the send's (raised out of the error handler, which stops the program).
        Assert.Equal("closed at 0", twin.Pendant.Lines[0]);
        Assert.DoesNotContain("never closed", twin.Pendant.Lines);
        Assert.Contains(twin.Pendant.Lines, l => l.Contains("SocketSend: The connection is closed.", StringComparison.Ordinal));
        Assert.NotEmpty(thrown);
        Assert.All(thrown, t => Assert.Equal(nameof(RapidRuntimeException), t));
    }

    [Fact]
    public void Outbox_SendToAPeerThatReset_FailsWithoutAnException_AndWriteStillSaysClosed()
    {
        using var listener = new Socket(AddressFamily.InterNetwork, SocketType.Stream, ProtocolType.Tcp);
        listener.Bind(new IPEndPoint(IPAddress.Loopback, 0));
        listener.Listen(1);
        using var client = new Socket(AddressFamily.InterNetwork, SocketType.Stream, ProtocolType.Tcp);
        client.Connect(listener.LocalEndPoint!);
        using Socket server = listener.Accept();
        var sends = new TwinHeldSends(); // owned by no thread: every write goes out at once
        var outbox = new TwinHeldOutbox(server, sends);
        client.LingerState = new LingerOption(true, 0);
        client.Close();
        var thrown = new List<string>();
        int thread = Environment.CurrentManagedThreadId;
        void Record(object? sender, FirstChanceExceptionEventArgs e)
        {
            if (Environment.CurrentManagedThreadId == thread)
            {
                thrown.Add(e.Exception.GetType().Name);
            }
        }

        AppDomain.CurrentDomain.FirstChanceException += Record;
        bool first, second;
        try
        {
            first = outbox.TryWrite("ab"u8);
            second = outbox.TryWrite("cd"u8);
        }
        finally
        {
            AppDomain.CurrentDomain.FirstChanceException -= Record;
        }

        Assert.False(first);
        Assert.False(second);
        Assert.Empty(thrown);
        Assert.Throws<IOException>(() => outbox.Write("ef"u8));
    }
}
