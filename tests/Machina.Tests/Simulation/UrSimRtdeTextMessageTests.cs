using System.Buffers.Binary;
using System.Net.Sockets;
using Machina.Simulation;
using Machina.Tests.Support;

namespace Machina.Tests.Simulation;

/// <summary>
/// RTDE package 77 from a client (UR's RTDE client library's <c>send_message(message, source, type)</c>: message length, message,
/// source length, source, level), which a UR puts in its log. The twin read and dropped it; now the pendant shows it.
/// </summary>
public class UrSimRtdeTextMessageTests
{
    [Fact]
    public async Task ClientTextMessage_ShownOnThePendant_AMalformedOneAnError()
    {
        await using var controller = new VirtualUrController(new VirtualUrControllerOptions { InstantExecution = true });
        await controller.StartAsync();
        using var tcp = new TcpClient();
        await tcp.ConnectAsync("127.0.0.1", controller.RtdePort).WaitAsync(TimeSpan.FromSeconds(15));
        using var client = GuideRtdeClient.Attach(tcp.GetStream());
        Assert.True(await client.NegotiateAsync());

        await tcp.GetStream().WriteAsync(TextMessage([5, .. "hello"u8, 13, .. "Python Client"u8, 3]));
        await tcp.GetStream().WriteAsync(TextMessage([9, .. "short"u8]));
        Assert.True(await client.NegotiateAsync()); // answered after both: the controller has read them

        Assert.Contains("Python Client: hello", controller.PendantMessages);
        Assert.Contains("RTDE: a text message of 6 bytes that does not hold a message, a source and a level.", controller.Errors);
    }

    private static byte[] TextMessage(byte[] payload)
    {
        var package = new byte[3 + payload.Length];
        BinaryPrimitives.WriteUInt16BigEndian(package, (ushort)package.Length);
        package[2] = 77;
        payload.CopyTo(package, 3);
        return package;
    }
}
