using Machina.Simulation;
using Machina.Tests.Online;
using static Machina.Tests.Online.OnlineTestSupport;
using static Machina.Tests.Online.UrOnlineTestSupport;

namespace Machina.Tests.Simulation;

/// <summary>
/// A virtual controller's request log writes a streamed request's text when the log is first read, and keeps that text in the
/// entry's place: every later read (the whole log, or since a count) hands the same string, written once, on every brand whose
/// log keeps what the text is written from (the UR driver's integers, the KUKA driver's values).
/// </summary>
public class RequestLogTextWrittenOnceTests
{
    [Fact]
    public void At_ReplacesAKeptEntryInPlace_WhatEveryLaterReadGives_AlsoAcrossTheRingsWrap()
    {
        var log = new VirtualControllerLog<object>(3);
        for (int i = 1; i <= 5; i++)
        {
            log.Add(i); // keeps 3, 4, 5: the ring has wrapped
        }
        Assert.Equal(3, log.Count);
        Assert.Equal(2, log.FirstSince(4));
        Assert.Equal(1, log.FirstSince(3));
        Assert.Equal(0, log.FirstSince(1));
        Assert.Equal(3, log.FirstSince(5));

        log.At(0) = "three";
        log.At(2) = "five";

        Assert.Equal(["three", 4, "five"], log.ToArray());
        var since = new List<object>();
        Assert.Equal(5, log.CopySince(3, since));
        Assert.Equal([4, "five"], since);
        log.Add(6);
        Assert.Equal([4, "five", 6], log.ToArray());
    }

    [Fact]
    public async Task Ur_ReceivedInstructions_TheirTextIsWrittenAtTheFirstRead_AndKept()
    {
        await using var controller = await StartUrAsync();
        Robot bot = await ConnectUrAsync(controller);
        bot.Wait(10);
        bot.Wait(20);
        bot.Wait(30);
        await bot.WaitForCompletionAsync().WaitAsync(Limit);

        var since = new List<string>();
        Assert.Equal(3, controller.ReceivedRequestsSince(1, since));
        IReadOnlyList<string> whole = controller.ReceivedRequests;
        IReadOnlyList<string> again = controller.ReceivedRequests;

        Assert.Equal(["1 9 10", "2 9 20", "3 9 30"], whole);
        Assert.Equal(["2 9 20", "3 9 30"], since);
        for (int i = 0; i < 3; i++)
        {
            Assert.Same(whole[i], again[i]); // one string per entry: the log kept the text it wrote
        }
        Assert.Same(since[0], whole[1]);
        Assert.Same(since[1], whole[2]);
        await bot.DisconnectAsync();
    }
}
