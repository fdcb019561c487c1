using System.Net;
using System.Net.Sockets;
using Machina.Simulation.Rapid;

namespace Machina.Tests.Simulation.Rapid;

/// <summary>
/// SocketReceive \ReadNoOfBytes (RAPID Instructions manual): the instruction waits until the asked number of bytes arrived, or its
/// \Time runs out (ERR_SOCK_TIMEOUT, and what arrived stays in the socket for the next receive). Before, the task took each
/// arrival's part, and a timeout midway lost it; \Str ignored the count.
/// </summary>
public class RapidSocketReceiveCountTests
{
    [Fact]
    public void ReadNoOfBytes_TimeoutBeforeTheCount_LeavesTheBytesForTheNextReceive_AndStrTakesTheCount()
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
              VAR rawbytes raw;
              VAR string text;
              VAR num n;
              PROC main()
                SocketCreate server;
                SocketBind server, "127.0.0.1", {{port}};
                SocketListen server;
                SocketAccept server, client \Time:=WAIT_MAX;
                SocketReceive client \RawData:=raw \ReadNoOfBytes:=4 \Time:=0.2;
                TPWrite "next";
                SocketSend client \Str:="go";
                SocketReceive client \RawData:=raw \ReadNoOfBytes:=4 \NoRecBytes:=n \Time:=10;
                TPWrite "bytes " \Num:=n;
                UnpackRawBytes raw \Network, 1, n \IntX:=DINT;
                TPWrite "got " \Num:=n;
                SocketReceive client \Str:=text \ReadNoOfBytes:=5 \Time:=10;
                TPWrite text;
                SocketReceive client \Str:=text \Time:=10;
                TPWrite text;
                SocketClose client;
                SocketClose server;
              ERROR
                IF ERRNO = ERR_SOCK_TIMEOUT THEN
                  TPWrite "timeout";
                  TRYNEXT;
                ENDIF
              ENDPROC
            ENDMODULE
            """));

        twin.StartTasks();
        using var client = new TcpClient();
        client.Connect(IPAddress.Loopback, port);
        NetworkStream stream = client.GetStream();
        stream.ReadTimeout = 10_000;
        stream.Write([0, 0]); // half of 258, big-endian: the first receive times out before the count
        var go = new byte[2];
        stream.ReadExactly(go); // sent after the timeout
        stream.Write([1, 2]); // the rest: the second receive takes all four
        stream.Write("abc"u8);
        stream.Write("defgh"u8);
        bool joined = twin.StopTasksWhenEnded(TimeSpan.FromSeconds(20));

        Assert.True(joined);
        Assert.Equal("go"u8.ToArray(), go);
        Assert.Equal(["timeout", "next", "bytes 4", "got 258", "abcde", "fgh"], twin.Pendant.Lines);
    }

    [Fact]
    public void ReadNoOfBytes_TheCountInSeveralPieces_IsTakenWhole()
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
              VAR byte data{6};
              VAR num n;
              PROC main()
                SocketCreate server;
                SocketBind server, "127.0.0.1", {{port}};
                SocketListen server;
                SocketAccept server, client \Time:=WAIT_MAX;
                SocketSend client \Str:="ready";
                SocketReceive client \Data:=data \ReadNoOfBytes:=6 \NoRecBytes:=n \Time:=10;
                TPWrite "bytes " \Num:=n;
                TPWrite ValToStr(data);
                SocketClose client;
                SocketClose server;
              ENDPROC
            ENDMODULE
            """));

        twin.StartTasks();
        using var client = new TcpClient();
        client.Connect(IPAddress.Loopback, port);
        NetworkStream stream = client.GetStream();
        stream.ReadTimeout = 10_000;
        var ready = new byte[5];
        stream.ReadExactly(ready); // the task waits in its receive now (its send went out when it waited)
        client.NoDelay = true;
        for (byte b = 1; b <= 6; b++)
        {
            stream.Write([b]);
            stream.Flush();
        }
        bool joined = twin.StopTasksWhenEnded(TimeSpan.FromSeconds(20));

        Assert.True(joined);
        Assert.Equal(["bytes 6", "[1,2,3,4,5,6]"], twin.Pendant.Lines);
    }
}
