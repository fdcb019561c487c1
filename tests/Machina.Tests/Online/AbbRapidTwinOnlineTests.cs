using System.Collections.Concurrent;
using Machina.Simulation;
using Machina.Simulation.Rapid;
using Machina.Tests.Support;

namespace Machina.Tests.Online;

/// <summary>
/// The virtual ABB with <see cref="VirtualAbbControllerOptions.RunsRapid"/>: Machina's RAPID driver and monitor run on the RAPID
/// interpreter inside it, and the library's online robot streams to them on the controller's ports.
/// </summary>
public class AbbRapidTwinOnlineTests
{
    private static async Task<VirtualAbbController> StartAsync()
    {
        var controller = new VirtualAbbController(new VirtualAbbControllerOptions
        {
            RunsRapid = true,
            InstantExecution = true,
            Model = RobotModels.Get("IRB 1600-8/1.45"),
        });
        await controller.StartAsync();
        return controller;
    }

    [Fact]
    public async Task HelloRobot_RunsOnTheDriverModules_SevenOfSevenExecuted()
    {
        await using VirtualAbbController controller = await StartAsync();
        var executed = new ConcurrentQueue<int>();
        Robot bot = await OnlineTestSupport.ConnectAsync(controller, b => b.ActionExecuted += (_, e) => executed.Enqueue(e.LastAction.Id));
        try
        {
            ReferencePrograms.HelloRobot(bot);
            await bot.WaitForCompletionAsync().WaitAsync(OnlineTestSupport.Limit);

            Assert.Equal([1, 2, 3, 4, 5, 6, 7], executed);
            Assert.Contains("Hello Robot!", controller.PendantMessages);
            Assert.Contains("Machina client connected", controller.PendantMessages);
            Assert.Equal(RapidProgramState.Running, controller.Twin!.Task().State);
            Assert.Equal(RapidProgramState.Running, controller.Twin.Task(VirtualAbbController.MonitorTask).State);
            Assert.Equal(90, controller.Twin.Arm.Joints.J5, 6);
        }
        finally
        {
            await bot.DisconnectAsync();
        }
    }

    [Fact]
    public async Task UnreachableMove_DriverTaskStops_HostReportsFailedAction50050()
    {
        await using VirtualAbbController controller = await StartAsync();
        var failed = new TaskCompletionSource<ActionFailedArgs>(TaskCreationOptions.RunContinuationsAsynchronously);
        Robot bot = await OnlineTestSupport.ConnectAsync(controller, b => b.ActionFailed += (_, e) => failed.TrySetResult(e));
        try
        {
            // The failure report travels on the monitor's connection: wait until the monitor serves the host (it may connect
            // a moment after the driver). A failure before that is not reported yet: see issue 22's notes.
            await Eventually.TrueAsync(() => controller.MonitorReportsSent > 0, "the monitor to serve the host", OnlineTestSupport.Limit);
            bot.MoveTo(4000, 0, 600);
            ActionFailedArgs e = await failed.Task.WaitAsync(OnlineTestSupport.Limit);

            Assert.Equal("50050", e.Failure.ControllerCode);
            Assert.Equal(1, e.Action.Id);
            Assert.Contains(controller.PendantMessages, m => m.StartsWith("50050 Position outside reach", StringComparison.Ordinal) && m.EndsWith("task T_ROB1)", StringComparison.Ordinal));
            Assert.Equal(RapidProgramState.Failed, controller.Twin!.Task().State);
        }
        finally
        {
            await bot.DisconnectAsync();
        }
    }

    [Fact]
    public async Task RunsRapid_WithoutModel_RunsOnAnIrb1600()
    {
        await using var controller = new VirtualAbbController(new VirtualAbbControllerOptions { RunsRapid = true, Model = null, InstantExecution = true });
        await controller.StartAsync();

        Assert.Equal("IRB 1600-8/1.45", controller.Twin!.Arm.Model.Name);
        Assert.Null(controller.Model);
    }
}
