using System.Net;
using System.Net.Sockets;
using System.Text;
using Machina.Simulation.Rapid;

namespace Machina.Tests.Simulation.Rapid;

/// <summary>
/// UDP sockets (SocketCreate \UDP, SocketBind, SocketSendTo, SocketReceiveFrom), as sensor and logger tasks use them: a program of our
/// own greets a client of the test, answers its datagram to the address it came from, reads raw bytes, and times out.
/// </summary>
public class RapidUdpTests
{
    [Fact]
    public async Task AProgram_SendsTo_AndReceivesFrom_AClientOnLoopback()
    {
        using var client = new UdpClient(new IPEndPoint(IPAddress.Loopback, 0));
        int clientPort = ((IPEndPoint)client.Client.LocalEndPoint!).Port;
        var twin = new RapidTwinController();
        twin.Load(("T.mod", $$"""
            MODULE T
              VAR socketdev udp;
              VAR string msg;
              VAR string sender;
              VAR num senderPort;
              VAR num n;
              VAR num value;
              VAR rawbytes raw;
              PROC main()
                SocketCreate udp \UDP;
                SocketBind udp, "127.0.0.1", 0;
                SocketSendTo udp, "127.0.0.1", {{clientPort}} \Str:="hello";
                SocketReceiveFrom udp \Str:=msg, sender, senderPort \Time:=20;
                TPWrite "from client: " + msg + " (" + sender + ", port matches " + ValToStr(senderPort = {{clientPort}}) + ")";
                SocketSendTo udp, sender, senderPort \Str:="echo " + msg;
                SocketReceiveFrom udp \RawData:=raw \NoRecBytes:=n, sender, senderPort \Time:=20;
                UnpackRawBytes raw, 1, value \Float4;
                SocketSendTo udp, sender, senderPort \Str:=NumToStr(n, 0) + " bytes: " + NumToStr(value, 2);
                SocketReceiveFrom udp \Str:=msg, sender, senderPort \Time:=0.2;
                TPWrite "not reached";
              ERROR
                TPWrite "timeout " \Bool:=ERRNO = ERR_SOCK_TIMEOUT;
                SocketClose udp;
              ENDPROC
            ENDMODULE
            """));
        using var stop = new CancellationTokenSource(TimeSpan.FromSeconds(60));
        Task<RapidProgramState> run = Task.Run(() => twin.Run("main", stop.Token));
        try
        {
            UdpReceiveResult hello = await client.ReceiveAsync(stop.Token);
            Assert.Equal("hello", Encoding.ASCII.GetString(hello.Buffer));
            await client.SendAsync(Encoding.ASCII.GetBytes("ping"), hello.RemoteEndPoint, stop.Token);
            UdpReceiveResult echo = await client.ReceiveAsync(stop.Token);
            Assert.Equal("echo ping", Encoding.ASCII.GetString(echo.Buffer));
            await client.SendAsync(BitConverter.GetBytes(2.5f), hello.RemoteEndPoint, stop.Token); // little-endian, as \Float4 reads it
            UdpReceiveResult answer = await client.ReceiveAsync(stop.Token);
            Assert.Equal("4 bytes: 2.5", Encoding.ASCII.GetString(answer.Buffer));
            Assert.Equal(hello.RemoteEndPoint, echo.RemoteEndPoint);
        }
        catch
        {
            await stop.CancelAsync(); // the program must not outlive a failed exchange
            throw;
        }

        RapidProgramState state = await run; // it ends by itself: its last receive times out after 0.2 s
        Assert.True(state == RapidProgramState.Finished, twin.Error);
        Assert.Equal(["from client: ping (127.0.0.1, port matches TRUE)", "timeout TRUE"], twin.Pendant.Lines);
    }
}
