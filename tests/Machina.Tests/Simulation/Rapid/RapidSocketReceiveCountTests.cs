using System.Net;
using System.Net.Sockets;
using Machina.Simulation.Rapid;

namespace Machina.Tests.Simulation.Rapid;

/// <summary>
/// SocketReceive \ReadNoOfBytes is how many bytes to take at most: the receive waits until something arrived (or \Time runs out,
/// ERR_SOCK_TIMEOUT) and takes what is there, up to the count; \NoRecBytes says how many. Programs written for controllers read
/// it so (a GoFa server and a socket server's test suite written against RobotStudio ask 1,024 bytes and read \NoRecBytes; the
/// suite sends fewer bytes than it announced and expects the short read). Session 32 made the twin wait for the whole count:
/// those programs never got an answer.
/// </summary>
public class RapidSocketReceiveCountTests
{
    [Fact]
    public void ReadNoOfBytes_TakesWhatArrived_AtMostTheCount_AndATimeoutTakesNothing()
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
              VAR num v;
              PROC main()
                SocketCreate server;
                SocketBind server, "127.0.0.1", {{port}};
                SocketListen server;
                SocketAccept server, client \Time:=WAIT_MAX;
                SocketReceive client \RawData:=raw \ReadNoOfBytes:=1024 \Time:=0.2;
                TPWrite "next";
                SocketSend client \Str:="go";
                SocketReceive client \RawData:=raw \ReadNoOfBytes:=1024 \NoRecBytes:=n \Time:=10;
                TPWrite "bytes " \Num:=n;
                UnpackRawBytes raw \Network, 1, v \IntX:=DINT;
                TPWrite "got " \Num:=v;
                SocketSend client \Str:="ok";
                SocketReceive client \Str:=text \ReadNoOfBytes:=5 \NoRecBytes:=n \Time:=10;
                TPWrite text + " " + NumToStr(n, 0);
                SocketReceive client \Str:=text \ReadNoOfBytes:=80 \NoRecBytes:=n \Time:=10;
                TPWrite text + " " + NumToStr(n, 0);
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
        var go = new byte[2];
        stream.ReadExactly(go); // sent after the first receive timed out with nothing arrived
        stream.Write([0, 0, 1, 2]); // four bytes where 1,024 were asked: the receive takes them
        var ok = new byte[2];
        stream.ReadExactly(ok);
        stream.Write("abcdefgh"u8); // \ReadNoOfBytes:=5 takes five, the next receive the other three
        bool joined = twin.StopTasksWhenEnded(TimeSpan.FromSeconds(20));

        Assert.True(joined);
        Assert.Equal("go"u8.ToArray(), go);
        Assert.Equal("ok"u8.ToArray(), ok);
        Assert.Equal(["timeout", "next", "bytes 4", "got 258", "abcde 5", "fgh 3"], twin.Pendant.Lines);
    }

    [Fact]
    public void ReadNoOfBytes_BelowOne_StopsTheProgramWithAnArgumentError()
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
              PROC main()
                SocketCreate server;
                SocketBind server, "127.0.0.1", {{port}};
                SocketListen server;
                SocketAccept server, client \Time:=WAIT_MAX;
                SocketReceive client \Data:=data \ReadNoOfBytes:=0 \Time:=10;
                TPWrite "received";
              ENDPROC
            ENDMODULE
            """));

        twin.StartTasks();
        using var client = new TcpClient();
        client.Connect(IPAddress.Loopback, port);
        client.GetStream().Write([1, 2, 3]);
        bool joined = twin.StopTasksWhenEnded(TimeSpan.FromSeconds(20));

        Assert.True(joined);
        Assert.DoesNotContain("received", twin.Pendant.Lines);
        Assert.Contains(twin.Pendant.Lines, l => l.Contains("\\ReadNoOfBytes 0 is outside 1..1024", StringComparison.Ordinal));
    }
}
