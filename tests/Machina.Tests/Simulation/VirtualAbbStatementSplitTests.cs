using Machina.Simulation;

namespace Machina.Tests.Simulation;

/// <summary>
/// The virtual ABB's reader counts each request as it arrives (issue 45, perf52w: a statement is cut from the arrival where it
/// lies, and one begun in an earlier arrival is joined): requests written in pieces that cut ids, numbers, the quoted text and
/// the ';' apart are received, logged and executed exactly as when written whole. However the loopback groups the pieces, the
/// outcome must be the same.
/// </summary>
public class VirtualAbbStatementSplitTests
{
    [Fact]
    public async Task RequestsWrittenInPieces_ReceivedLoggedAndExecutedAsWhole()
    {
        await using var controller = new VirtualAbbController(new VirtualAbbControllerOptions { InstantExecution = true });
        await controller.StartAsync();
        using var client = await RawAbbClient.ConnectAsync(controller.Port);
        await client.ReadHandshakeAsync();
        string[] pieces = ["  @", "1 4", " 100", ";\r\n@2 5 0", ";", "@3 1 400 0 300 0 0 1 0;@4 7 \"a", ";b", "\";  @0", " 9;"];

        foreach (string piece in pieces)
        {
            await client.SendAsync(piece);
            await Task.Delay(20); // lets the reader take most pieces apart (the outcome must not depend on it)
        }
        var acks = await client.ReadMessagesAsync(5);

        Assert.Equal(["@1 4;", "@2 5;", "@3 1;", "@4 7;", "9;"], acks.Select(a => a.ToString()));
        Assert.Equal(["@1 4 100;", "@2 5 0;", "@3 1 400 0 300 0 0 1 0;", "@4 7 \"a;b\";", "@0 9;"], controller.ReceivedRequests);
        Assert.Equal([1, 2, 3, 4], controller.ExecutedIds);
        Assert.Equal((5, 5, 5), (controller.RequestsReceived, controller.RequestsExecuted, controller.AcknowledgementsSent));
    }
}
