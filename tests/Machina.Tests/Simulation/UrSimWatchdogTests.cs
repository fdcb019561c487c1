using System.Buffers.Binary;
using System.Text;
using Machina.Simulation;
using Machina.Simulation.UrScript;
using Machina.Tests.Support;

namespace Machina.Tests.Simulation;

/// <summary>
/// What ur_rtde's control script and UR's Script Manual need of the virtual UR beyond plain motion: the RTDE watchdog
/// (<c>rtde_set_watchdog</c>: an input not updated within 1 / min_frequency pauses or stops the program, or is ignored), a
/// blocking popup that the dashboard's <c>close popup</c> ends, and the RTDE sender's deadlines (a late sender catches up).
/// </summary>
public class UrSimWatchdogTests
{
    private const string WatchdogMessage = "RTDE watchdog: no update of input_int_register_0 within 0.1 s (10 Hz): ";

    [Theory]
    [InlineData("stop", "program stopped")]
    [InlineData("pause", "program paused")]
    [InlineData("ignore", "ignored")]
    [InlineData("PAUSE", "program paused")] // in any case: UR's RTDE Python client's example program (rtde_control_loop.urp) asks so
    public async Task Watchdog_InputUpdatedInTime_RunsOn_ThenMissedUpdate_TakesTheAction(string asked, string done)
    {
        string action = asked.ToLowerInvariant();
        var clock = new ManualClock();
        await using var controller = new VirtualUrController(new VirtualUrControllerOptions { TimeProvider = clock });
        await controller.StartAsync();
        using var client = await GuideRtdeClient.ConnectAsync(controller.RtdePort);
        Assert.True(await client.NegotiateAsync());
        var (id, types) = await client.SetupInputsAsync("input_int_register_0");
        Assert.Equal(["INT32"], types);
        Assert.True(await client.StartAsync());
        using var script = await UrSimClientInterfaceTests.ConnectAsync(controller.Port);
        await script.GetStream().WriteAsync(Encoding.ASCII.GetBytes(
            $"def wd():\n  rtde_set_watchdog(\"input_int_register_0\", 10, \"{asked}\")\n  write_output_integer_register(1, 1)\n" +
            "  while True:\n    sleep(1)\n  end\nend\n"));
        await OnlineWait.UntilAsync(() => controller.Twin.Io.GetNumber(UrIoBanks.OutputIntRegisters, 1) == 1, "the watchdog to be set");
        Assert.Equal([("input_int_register_0", 10.0, action)], controller.Twin.Watchdog.Armed);

        // Updates every 60 ms for 0.3 s: each within the watchdog's 0.1 s, so it never runs out.
        for (int i = 1; i <= 5; i++)
        {
            var value = new byte[4];
            BinaryPrimitives.WriteInt32BigEndian(value, i);
            await client.SendInputsAsync(id, value);
            await OnlineWait.UntilAsync(() => controller.Twin.Io.GetNumber(UrIoBanks.InputIntRegisters, 0) == i, "the update to arrive");
            clock.Advance(TimeSpan.FromMilliseconds(60));
        }
        Assert.DoesNotContain(controller.PendantMessages, m => m.StartsWith("RTDE watchdog", StringComparison.Ordinal));
        Assert.Equal(UrProgramState.Running, controller.Twin.State);

        // Then no update for 0.1 s.
        clock.Advance(TimeSpan.FromMilliseconds(100));
        await OnlineWait.UntilAsync(() => controller.PendantMessages.Contains(WatchdogMessage + done), "the watchdog to run out");
        switch (action)
        {
            case "stop":
                await OnlineWait.UntilAsync(() => controller.Twin.State == UrProgramState.Stopped, "the program to stop");
                Assert.Empty(controller.Twin.Watchdog.Armed); // "All watchdogs are removed on program stop"
                break;
            case "pause":
                Assert.True(controller.Twin.IsHeld);
                Assert.Equal(UrProgramState.Running, controller.Twin.State);
                break;
            default:
                Assert.False(controller.Twin.IsHeld);
                Assert.Equal(UrProgramState.Running, controller.Twin.State);
                break;
        }
        Assert.Single(controller.PendantMessages, m => m.StartsWith("RTDE watchdog", StringComparison.Ordinal));
    }

    [Fact]
    public async Task Watchdog_PausedProgram_IsEndedByTheNextScript_WhichRuns()
    {
        await using var controller = new VirtualUrController(new VirtualUrControllerOptions { InstantExecution = true });
        await controller.StartAsync();
        using var client = await GuideRtdeClient.ConnectAsync(controller.RtdePort);
        Assert.True(await client.NegotiateAsync());
        await client.SetupInputsAsync("input_int_register_0");
        Assert.True(await client.StartAsync());
        using var script = await UrSimClientInterfaceTests.ConnectAsync(controller.Port);
        await script.GetStream().WriteAsync(Encoding.ASCII.GetBytes(
            "def wd():\n  rtde_set_watchdog(\"input_int_register_0\", 10, \"pause\")\n  while True:\n    sleep(1)\n  end\nend\n"));
        await OnlineWait.UntilAsync(() => controller.PendantMessages.Contains(WatchdogMessage + "program paused"), "the watchdog to pause the program");
        Assert.True(controller.Twin.IsHeld);

        // As python-urx goes on after UR's RTDE example left the program paused: its next command is a program of its own.
        await script.GetStream().WriteAsync(Encoding.ASCII.GetBytes(
            "def next():\n  movej([0.3, -1.4, 1.4, -1.5, -1.57, 0.2], a=1, v=0.5)\n  write_output_integer_register(2, 7)\nend\n"));
        await OnlineWait.UntilAsync(() => controller.Twin.Io.GetNumber(UrIoBanks.OutputIntRegisters, 2) == 7, "the next program to run");
        Assert.False(controller.Twin.IsHeld);
        Assert.Equal(new[] { 0.3, -1.4, 1.4, -1.5, -1.57, 0.2 }, controller.Twin.JointsNow().ToArray().Select(d => Math.Round(d * Math.PI / 180, 6)));
    }

    [Fact]
    public async Task Popup_Blocking_SuspendsTheProgramUntilTheDashboardClosesIt()
    {
        await using var controller = new VirtualUrController(new VirtualUrControllerOptions { InstantExecution = true });
        await controller.StartAsync();
        using var dashboard = await UrSimDashboardTests.DashboardAsync(controller.DashboardPort);
        using var script = await UrSimClientInterfaceTests.ConnectAsync(controller.Port);
        await script.GetStream().WriteAsync(Encoding.ASCII.GetBytes(
            "def ask():\n  write_output_integer_register(2, 1)\n  popup(\"Tool changed?\", title=\"Operator\", blocking=True)\n" +
            "  write_output_integer_register(2, 7)\nend\n"));
        double Register() => controller.Twin.Io.GetNumber(UrIoBanks.OutputIntRegisters, 2);

        await OnlineWait.UntilAsync(() => controller.Twin.Popup == "Tool changed?", "the popup");
        Thread.Sleep(100); // a program that did not wait would have written 7 by now
        Assert.Equal(1, Register());
        Assert.True(controller.IsProgramRunning);
        Assert.Contains("Popup Operator: Tool changed?", controller.PendantMessages);

        Assert.Equal("closing popup", await UrSimDashboardTests.AskAsync(dashboard, "close popup"));
        await OnlineWait.UntilAsync(() => Register() == 7 && !controller.IsProgramRunning, "the program to go on and end");
        Assert.Null(controller.Twin.Popup);
    }

    [Fact]
    public async Task Popup_Blocking_StopEndsTheProgramAndClosesIt()
    {
        await using var controller = new VirtualUrController(new VirtualUrControllerOptions { InstantExecution = true });
        await controller.StartAsync();
        using var dashboard = await UrSimDashboardTests.DashboardAsync(controller.DashboardPort);
        using var script = await UrSimClientInterfaceTests.ConnectAsync(controller.Port);
        await script.GetStream().WriteAsync(Encoding.ASCII.GetBytes("def ask():\n  popup(\"Wait\", blocking=True)\n  write_output_integer_register(2, 7)\nend\n"));
        await OnlineWait.UntilAsync(() => controller.Twin.Popup == "Wait", "the popup");

        Assert.Equal("Stopped", await UrSimDashboardTests.AskAsync(dashboard, "stop"));
        Assert.Equal(UrProgramState.Stopped, controller.Twin.State);
        Assert.Null(controller.Twin.Popup);
        Assert.Equal(0, controller.Twin.Io.GetNumber(UrIoBanks.OutputIntRegisters, 2));
    }

    [Fact]
    public async Task Rtde_SenderLateBySeveralPeriods_CatchesUpWithEveryPackage()
    {
        var clock = new ManualClock();
        await using var controller = new VirtualUrController(new VirtualUrControllerOptions { InstantExecution = true, TimeProvider = clock });
        await controller.StartAsync();
        using var client = await GuideRtdeClient.ConnectAsync(controller.RtdePort);
        Assert.True(await client.NegotiateAsync());
        await client.SetupOutputsAsync(25, "timestamp");
        Assert.True(await client.StartAsync());
        await client.ReadDataAsync();
        var period = TimeSpan.FromMilliseconds(40);
        await OnlineWait.UntilAsync(() => clock.HasTimerDueIn(period), "the sender to wait for its next package");

        // Three periods at once (a sender woken late): the three packages due are all sent, and the next is due on the same beat.
        clock.Advance(3 * period);
        for (int i = 0; i < 3; i++)
        {
            await client.ReadDataAsync();
        }
        await OnlineWait.UntilAsync(() => clock.HasTimerDueIn(period), "the sender to wait for the package at 160 ms");
        Assert.Equal(4, controller.RtdePackagesSent);
    }
}
