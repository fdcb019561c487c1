using System.Collections.Concurrent;
using System.Net;
using System.Net.Sockets;
using System.Text;
using Machina.Simulation;
using Machina.Tests.Online;

namespace Machina.Tests.Reliability;

/// <summary>
/// Exactly once on UR under stalls (issue 28): a driver script held by a slow link and delivered after the host has moved on
/// starts an old program that replaces the current one. It must not make the host believe nothing ran.
/// </summary>
public class UrStaleProgramTests
{
    [Fact]
    public async Task HeldScriptDeliveredLate_ReplacesTheProgram_ReconnectResumesFromTheRealProgress_NothingRunsTwice()
    {
        await using var controller = new VirtualUrController(new VirtualUrControllerOptions { Model = null, InstantExecution = true });
        await controller.StartAsync();
        var lost = new ConcurrentQueue<ConnectionLostArgs>();
        var executed = new ConcurrentQueue<int>();
        Robot bot = await UrOnlineTestSupport.ConnectUrAsync(controller, b =>
        {
            b.ConnectionLost += (_, e) => lost.Enqueue(e);
            b.ActionExecuted += (_, e) => executed.Enqueue(e.LastAction.Id);
        });
        try
        {
            string held = controller.LastScript!; // the first upload, as a slow link could still be holding a copy of it
            await bot.DisconnectAsync();
            await bot.ConnectAsync("127.0.0.1", controller.Port).WaitAsync(OnlineTestSupport.Limit);
            Assert.NotEqual(InstanceOf(held), controller.InstanceRegister);

            // Moves reach the controller (as many as the session streams ahead); the driver runs the first, its acknowledgement
            // leaves and the link drops: the moves after it were in the dropped connection, so the driver never reads them.
            controller.StopAnswering();
            controller.CloseConnectionAfter(1);
            for (int i = 0; i < 10; i++)
            {
                bot.MoveTo(400 + i, 0, 300);
            }
            await OnlineTestSupport.EventuallyAsync(() => controller.RequestsReceived >= 1, "the first move to run (its acknowledgement is held)");
            controller.ResumeAnswering();
            await OnlineTestSupport.EventuallyAsync(() => !lost.IsEmpty && controller.BufferedRequestCount == 0 && controller.ExecutedIds.Count == controller.RequestsReceived,
                "the link to drop and the program to run what it received");
            int[] ran = [.. controller.ExecutedIds];
            Assert.True(ran.Length >= 1, "the controller ran no move");

            // The held script arrives now: its program replaces the idle one and cannot connect back (that server is gone).
            using (var late = new TcpClient())
            {
                await late.ConnectAsync(IPAddress.Loopback, controller.Port);
                await late.GetStream().WriteAsync(Encoding.ASCII.GetBytes(held));
                await OnlineTestSupport.EventuallyAsync(() => controller.InstanceRegister == InstanceOf(held) && !controller.IsProgramRunning, "the late program to start and stop");
            }

            await bot.ConnectAsync("127.0.0.1", controller.Port).WaitAsync(OnlineTestSupport.Limit);
            bot.MoveTo(500, 0, 300);
            Assert.True(bot.WaitForCompletion(OnlineTestSupport.Limit));

            // Each of the eleven moves ran once, in order: those the old program ran were not sent again.
            Assert.Equal(Enumerable.Range(ran[0], 11), controller.ExecutedIds);
            Assert.Equal(11, executed.Count);
            Assert.Equal(executed.Distinct().Count(), executed.Count);
            Assert.True(controller.State.Position.IsSimilar(new Vector(500, 0, 300), 1e-6), controller.State.Position.ToString());
        }
        finally
        {
            await bot.DisconnectAsync();
        }
    }

    /// <summary>The instance number a driver script publishes (its <c>INSTANCE = n</c> line).</summary>
    private static int InstanceOf(string script)
    {
        System.Text.RegularExpressions.Match m = System.Text.RegularExpressions.Regex.Match(script, @"^[ \t]*INSTANCE[ \t]*=[ \t]*(-?[0-9]+)", System.Text.RegularExpressions.RegexOptions.Multiline);
        Assert.True(m.Success, "the driver script has no INSTANCE line");
        return int.Parse(m.Groups[1].Value, System.Globalization.CultureInfo.InvariantCulture);
    }
}
