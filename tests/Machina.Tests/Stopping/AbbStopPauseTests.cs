using Machina.Simulation;
using Machina.Tests.Online;

namespace Machina.Tests.Stopping;

/// <summary>
/// Robot.Stop / Pause / Resume on the ABB twin that runs the unchanged RAPID driver and monitor: the monitor task takes the command
/// out of band (StopMove / StartMove \AllMotionTasks); on a stop the driver's interrupt on machinaStopRequest clears the path and
/// fails the move under way. The runs themselves are the <see cref="StopPauseContract{TController, TState}"/>.
/// </summary>
public class AbbStopPauseTests : StopPauseContract<VirtualAbbController, VirtualAbbState>
{
    /// <inheritdoc/>
    protected override async Task<VirtualAbbController> StartAsync()
    {
        var controller = new VirtualAbbController(new VirtualAbbControllerOptions());
        await controller.StartAsync().WaitAsync(Long);
        return controller;
    }

    /// <inheritdoc/>
    protected override Task<Robot> ConnectAsync(VirtualAbbController controller, Action<Robot>? configure = null) =>
        OnlineTestSupport.ConnectAsync(controller, configure);

    /// <inheritdoc/>
    protected override string WriteOutput => "WriteDigital(\"DO_2\", true);";

    /// <inheritdoc/>
    protected override string OutputKey => "DO_2";
}
