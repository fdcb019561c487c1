using System.Collections.Concurrent;
using Machina.Simulation;
using Machina.Tests.Online;
using Machina.Tests.Support;

namespace Machina.Tests.Inputs;

/// <summary>
/// WaitForDigital online on the twins that run the unchanged driver programs: an input a test sets releases the wait, and a
/// wait that reaches its limit fails the action with the controller's reason, nothing after it running.
/// </summary>
public class WaitForDigitalTwinTests
{
    /// <summary>How long a wait that must stay blocked is watched: a wrong driver would pass it at once.</summary>
    private static readonly TimeSpan Blocked = TimeSpan.FromMilliseconds(400);

    private static async Task<VirtualAbbController> StartAbbAsync(bool instant)
    {
        var controller = new VirtualAbbController(new VirtualAbbControllerOptions
        {
            RunsRapid = true,
            InstantExecution = instant,
            Model = RobotModels.Get("IRB 1600-8/1.45"),
        });
        await controller.StartAsync();
        return controller;
    }

    [Fact]
    public async Task Abb_InputSetLater_ReleasesTheWait_ThenTheNextActionRuns()
    {
        await using VirtualAbbController controller = await StartAbbAsync(instant: false);
        var executed = new ConcurrentQueue<int>();
        Robot bot = await OnlineTestSupport.ConnectAsync(controller, b => b.ActionExecuted += (_, e) => executed.Enqueue(e.LastAction.Id));
        try
        {
            bot.Message("before");
            bot.WaitForDigital("DI_3", true);
            bot.Message("after");
            // The driver runs the message, then acknowledges it: wait for both (the host's event may come well after the pendant line).
            await OnlineTestSupport.EventuallyAsync(() => controller.PendantMessages.Contains("before") && executed.Contains(1), "the driver to run the first message");
            await Task.Delay(Blocked);
            Assert.Equal([1], executed);
            Assert.DoesNotContain("after", controller.PendantMessages);

            controller.SetDigitalInput("DI_3", true);
            await bot.WaitForCompletionAsync().WaitAsync(OnlineTestSupport.Limit);

            Assert.Equal([1, 2, 3], executed);
            Assert.Contains("after", controller.PendantMessages);
        }
        finally
        {
            await bot.DisconnectAsync();
        }
    }

    [Fact]
    public async Task Abb_InputAlreadySet_WaitPassesAtOnce()
    {
        await using VirtualAbbController controller = await StartAbbAsync(instant: true);
        controller.SetDigitalInput("DI_2", true);
        Robot bot = await OnlineTestSupport.ConnectAsync(controller);
        try
        {
            bot.WaitForDigital("DI_2", true);
            bot.WaitForDigital("DI_5", false, 1000);
            bot.Message("done");
            await bot.WaitForCompletionAsync().WaitAsync(OnlineTestSupport.Limit);

            Assert.Contains("done", controller.PendantMessages);
        }
        finally
        {
            await bot.DisconnectAsync();
        }
    }

    [Fact]
    public async Task Abb_Timeout_FailsTheActionWithErrWaitMaxTime_NothingAfterRuns()
    {
        await using VirtualAbbController controller = await StartAbbAsync(instant: true);
        var failed = new TaskCompletionSource<ActionFailedArgs>(TaskCreationOptions.RunContinuationsAsynchronously);
        Robot bot = await OnlineTestSupport.ConnectAsync(controller, b => b.ActionFailed += (_, e) => failed.TrySetResult(e));
        try
        {
            await Eventually.TrueAsync(() => controller.MonitorReportsSent > 0, "the monitor to serve the host", OnlineTestSupport.Limit);
            bot.WaitForDigital("DI_4", true, 500);
            bot.Message("after");
            ActionFailedArgs e = await failed.Task.WaitAsync(OnlineTestSupport.Limit);

            Assert.Equal("3", e.Failure.ControllerCode);
            Assert.Equal(1, e.Action.Id);
            Assert.Equal("The input did not reach its value within the time limit (WaitDI \\MaxTime, RAPID error ERR_WAIT_MAXTIME); the driver program stopped.", e.Reason);
            Assert.Contains("Machina: request 1 failed, code 3", controller.PendantMessages);
            Assert.DoesNotContain("after", controller.PendantMessages);
        }
        finally
        {
            await bot.DisconnectAsync();
        }
    }

    [Fact]
    public async Task Ur_InputSetLater_ReleasesTheWait_ThenTheNextActionRuns()
    {
        await using VirtualUrController controller = await UrOnlineTestSupport.StartUrAsync(new VirtualUrControllerOptions());
        var executed = new ConcurrentQueue<int>();
        Robot bot = await UrOnlineTestSupport.ConnectUrAsync(controller, b => b.ActionExecuted += (_, e) => executed.Enqueue(e.LastAction.Id));
        try
        {
            bot.WriteDigital(1, true);
            bot.WaitForDigital(6, true);
            bot.WriteDigital(2, true);
            await OnlineTestSupport.EventuallyAsync(() => executed.Contains(1), "the first output to be set");
            await Task.Delay(Blocked);
            Assert.Equal([1], executed);

            controller.SetDigitalInput(6, true);
            await bot.WaitForCompletionAsync().WaitAsync(OnlineTestSupport.Limit);

            Assert.Equal([1, 2, 3], executed);
        }
        finally
        {
            await bot.DisconnectAsync();
        }
    }

    [Fact]
    public async Task Ur_Timeout_FailsTheAction_NothingAfterRuns()
    {
        await using VirtualUrController controller = await UrOnlineTestSupport.StartUrAsync();
        var failed = new TaskCompletionSource<ActionFailedArgs>(TaskCreationOptions.RunContinuationsAsynchronously);
        var executed = new ConcurrentQueue<int>();
        Robot bot = await UrOnlineTestSupport.ConnectUrAsync(controller, b =>
        {
            b.ActionFailed += (_, e) => failed.TrySetResult(e);
            b.ActionExecuted += (_, e) => executed.Enqueue(e.LastAction.Id);
        });
        try
        {
            bot.WaitForDigital(0, true, 300, toolPin: true);
            bot.WriteDigital(2, true);
            ActionFailedArgs e = await failed.Task.WaitAsync(OnlineTestSupport.Limit);

            Assert.Equal(1, e.Action.Id);
            Assert.Empty(executed);
            // The driver halts without a runtime error: the host names what RTDE showed (no text from the real-time port).
            Assert.StartsWith("the program stopped (RTDE runtime_state 1", e.Reason, StringComparison.Ordinal);
            Assert.EndsWith("without running it", e.Reason, StringComparison.Ordinal);
        }
        finally
        {
            await bot.DisconnectAsync();
        }
    }

    [Fact]
    public async Task Kuka_InputSetLater_ReleasesTheWait_ThenTheNextActionRuns()
    {
        await using VirtualKukaController controller = await KukaTestSupport.StartKukaAsync(new VirtualKukaControllerOptions());
        var (bot, executed, _) = await KukaTestSupport.ConnectKukaAsync(controller);
        try
        {
            bot.WriteDigital(1, true);
            bot.WaitForDigital(7, true);
            bot.WriteDigital(2, true);
            await OnlineTestSupport.EventuallyAsync(() => executed.Contains(1), "the first output to be set");
            await Task.Delay(Blocked);
            Assert.Equal([1], executed);

            controller.SetDigitalInput(7, true);
            await bot.WaitForCompletionAsync().WaitAsync(OnlineTestSupport.Limit);

            Assert.Equal([1, 2, 3], executed);
        }
        finally
        {
            await bot.DisconnectAsync();
        }
    }

    [Fact]
    public async Task Kuka_Timeout_FailsTheActionWithCode6_NothingAfterRuns()
    {
        await using VirtualKukaController controller = await KukaTestSupport.StartKukaAsync(new VirtualKukaControllerOptions());
        var failed = new TaskCompletionSource<ActionFailedArgs>(TaskCreationOptions.RunContinuationsAsynchronously);
        var (bot, executed, _) = await KukaTestSupport.ConnectKukaAsync(controller, b => b.ActionFailed += (_, e) => failed.TrySetResult(e));
        try
        {
            bot.Do("WaitForDigital(8, true, 300); WriteDigital(2, true);"); // issued together: the write is cancelled, never issued after the failure
            ActionFailedArgs e = await failed.Task.WaitAsync(OnlineTestSupport.Limit);

            Assert.Equal(1, e.Action.Id);
            Assert.Equal("6", e.Failure.ControllerCode);
            Assert.Equal("Input did not change within the time limit: the wait for $IN timed out.", e.Reason);
            Assert.Equal([2], e.CancelledActions.Select(a => a.Id));
            Assert.Empty(executed);
        }
        finally
        {
            await bot.DisconnectAsync();
        }
    }
}
