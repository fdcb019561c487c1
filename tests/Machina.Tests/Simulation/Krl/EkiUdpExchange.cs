using System.Net;
using System.Net.Sockets;
using System.Text;
using Machina.Simulation.Krl;
using static Machina.Tests.Online.OnlineTestSupport;

namespace Machina.Tests.Simulation.Krl;

/// <summary>One exchange with a program's UDP EthernetKRL server: a datagram to it once its channel is open, its answer back.</summary>
internal static class EkiUdpExchange
{
    /// <summary>Runs the loaded program, sends <paramref name="datagram"/> to <paramref name="channel"/>, and returns its answer and how the program ended.</summary>
    public static async Task<(KrlProgramState State, string Answer)> RunAsync(KrlTwinController twin, string channel, string datagram)
    {
        using var stop = new CancellationTokenSource(Limit);
        Task<KrlProgramState> run = Task.Run(() => twin.Run(null, stop.Token));
        await EventuallyAsync(() => twin.EkiPort(channel) > 0 || run.IsCompleted, "the channel to be open");

        using var client = new UdpClient(new IPEndPoint(IPAddress.Loopback, 0));
        await client.SendAsync(Encoding.UTF8.GetBytes(datagram), new IPEndPoint(IPAddress.Loopback, twin.EkiPort(channel)));
        UdpReceiveResult answer = await client.ReceiveAsync(stop.Token).AsTask().WaitAsync(Limit);
        KrlProgramState state = await run.WaitAsync(Limit);
        return (state, Encoding.UTF8.GetString(answer.Buffer));
    }
}
