using System.Collections.Concurrent;
using static Machina.Tests.Online.KukaTestSupport;
using static Machina.Tests.Online.OnlineTestSupport;

namespace Machina.Tests.Online;

/// <summary>What a device driver logs reaches the robot's log sinks on the event pump, never inside the session's loop.</summary>
public class DriverLogTests
{
    [Fact]
    public async Task DriverWarning_WhileReleasing_WrittenOnTheEventPumpNotInsideTheIssuingCall()
    {
        await using var controller = await StartKukaAsync();
        int insideIssue = -1;   // the id of the thread inside bot.Message while it runs, else -1
        var seen = new ConcurrentQueue<(string Message, bool InsideIssue)>();
        var (bot, _, _) = await ConnectKukaAsync(controller, b => b.Logger.AddSink(
            e => seen.Enqueue((e.Message, Volatile.Read(ref insideIssue) == Environment.CurrentManagedThreadId)), LogLevel.WARNING));

        Volatile.Write(ref insideIssue, Environment.CurrentManagedThreadId);
        bot.Message(new string('a', 70) + " and the rest is cut");   // released at once: the KUKA driver warns while encoding it
        Volatile.Write(ref insideIssue, -1);
        await bot.WaitForCompletionAsync().WaitAsync(Limit);

        var (message, inside) = Assert.Single(seen, s => s.Message.StartsWith("KUKA messages", StringComparison.Ordinal));
        Assert.Equal($"KUKA messages hold 80 characters: the message of action 1 is shown cut to \"{new string('a', 70)} and the r\".", message);
        Assert.False(inside);
        await bot.DisconnectAsync();
    }
}
