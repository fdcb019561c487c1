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
            // The failure report travels on the monitor's connection, which the host may open a moment after the driver's: the
            // monitor keeps a report until a client takes it, so the move is issued at once (either order is reported).
            bot.MoveTo(4000, 0, 600);
            ActionFailedArgs e = await failed.Task.WaitAsync(OnlineTestSupport.Limit);

            Assert.Equal("50050", e.Failure.ControllerCode);
            Assert.Equal(1, e.Action.Id);
            await OnlineTestSupport.EventuallyAsync(() => controller.Errors.Count > 0, "the error in controller.Errors");
            Assert.Contains(controller.Errors, m => m.StartsWith("50050 Position outside reach", StringComparison.Ordinal) && m.EndsWith("task T_ROB1)", StringComparison.Ordinal));
            Assert.Equal(RapidProgramState.Failed, controller.Twin!.Task().State);
        }
        finally
        {
            await bot.DisconnectAsync();
        }
    }

    /// <summary>
    /// A move that fails while nobody watches the monitor: its task keeps the report ("$26 id code;") and sends it, before the
    /// first state report, to the client that connects afterwards.
    /// </summary>
    [Fact]
    public async Task MoveFailsBeforeTheMonitorHasAClient_FirstMonitorClientLearnsIt()
    {
        await using VirtualAbbController controller = await StartAsync();
        using var driver = await Simulation.RawAbbClient.ConnectAsync(controller.Port);
        await driver.ReadHandshakeAsync();
        // The monitor task orders its error interrupt as it starts (on an IRC5 long before a host connects).
        await Eventually.TrueAsync(() => controller.Twin!.Task(VirtualAbbController.MonitorTask).OrdersErrorInterrupts, "the monitor to order its error interrupt", OnlineTestSupport.Limit);

        await driver.SendAsync("@7 1 4000 0 600 0 0 1 0;");
        await Eventually.TrueAsync(() => controller.Twin!.Task().State == RapidProgramState.Failed, "the driver task to stop on the move", OnlineTestSupport.Limit);
        using var monitor = await Simulation.RawAbbClient.ConnectAsync(controller.MonitorPort);
        List<AbbMessage> messages = await monitor.ReadMessagesAsync(2);

        Assert.StartsWith("$26 7 50050;$24 ", monitor.RawText, StringComparison.Ordinal);
        Assert.Equal(26, messages[0].Code);
        Assert.Equal([7, 50050], messages[0].Values.ToArray());
        Assert.Equal(24, messages[1].Code);
        Assert.StartsWith("50050 Position outside reach", controller.Twin!.Task().Error, StringComparison.Ordinal);
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
