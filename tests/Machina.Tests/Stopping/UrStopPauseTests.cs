using Machina.Simulation;
using Machina.Tests.Online;

namespace Machina.Tests.Stopping;

/// <summary>
/// Robot.Stop / Pause / Resume on the UR twin that runs the unchanged driver script, through its dashboard (the runs are the
/// <see cref="StopPauseContract{TController, TState}"/>); a stopped UR program ends, so the contract's new connection after a
/// stop is not part of it here.
/// </summary>
public class UrStopPauseTests : StopPauseContract<VirtualUrController, VirtualUrState>
{
    /// <inheritdoc/>
    protected override Task<VirtualUrController> StartAsync() => UrOnlineTestSupport.StartUrAsync(new VirtualUrControllerOptions());

    /// <inheritdoc/>
    protected override Task<Robot> ConnectAsync(VirtualUrController controller, Action<Robot>? configure = null) =>
        UrOnlineTestSupport.ConnectUrAsync(controller, configure);

    /// <inheritdoc/>
    protected override string WriteOutput => "WriteDigital(2, true);";

    /// <inheritdoc/>
    protected override string OutputKey => "2";

    /// <inheritdoc/>
    protected override double ArrivalTolerance => 1e-3;

    /// <inheritdoc/>
    protected override bool RunsAgainAfterStop => false;

    [Fact]
    public void Stop_Offline_IsRefused()
    {
        var bot = Robot.Create("T", "UR");
        var e = Assert.Throws<InvalidOperationException>(() => bot.Stop());
        Assert.Equal("Cannot stop while the robot is offline; call ControlMode(\"online\") first.", e.Message);
    }
}
