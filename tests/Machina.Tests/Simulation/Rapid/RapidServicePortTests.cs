using System.Net;
using System.Net.Sockets;
using System.Text;
using Machina.Simulation.Rapid;

namespace Machina.Tests.Simulation.Rapid;

/// <summary>
/// A socket server written for a real controller binds to the IRC5 service port's fixed address, 192.168.125.1: on the twin that
/// address is the controller's own, so the server listens where the twin serves (127.0.0.1 here) and a client reaches it there.
/// </summary>
public class RapidServicePortTests
{
    [Fact]
    public void AServerBoundToTheServicePortAddress_ListensWhereTheTwinServes()
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
              PROC main()
                SocketCreate server;
                SocketBind server, "192.168.125.1", {{port}};
                SocketListen server;
                SocketAccept server, client \Time:=WAIT_MAX;
                SocketReceive client \Str:=text \Time:=10;
                SocketSend client \Str:="echo " + text;
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
        stream.Write("hi"u8);
        var answer = new byte[7];
        stream.ReadExactly(answer);
        bool ended = twin.StopTasksWhenEnded(TimeSpan.FromSeconds(10));

        Assert.Equal("echo hi", Encoding.ASCII.GetString(answer));
        Assert.True(ended, twin.Task().Error);
        Assert.Equal(RapidProgramState.Finished, twin.Task().State);
    }
}
