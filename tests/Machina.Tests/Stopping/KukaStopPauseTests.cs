using Machina.Simulation;
using Machina.Tests.Online;

namespace Machina.Tests.Stopping;

/// <summary>
/// Robot.Stop / Pause / Resume on the KRL twin that runs the unchanged drivers/kuka: <c>&lt;STOP/&gt;</c> and <c>&lt;PAUSE/&gt;</c> on the
/// driver's EthernetKRL channel set $FLAG[4] / $FLAG[5], whose interrupts BRAKE the motion; a stop fails the action under way
/// (code 7) and ends it with RESUME, a pause waits in its interrupt routine for <c>&lt;RESUME/&gt;</c>. The runs are the
/// <see cref="StopPauseContract{TController, TState}"/>.
/// </summary>
public class KukaStopPauseTests : StopPauseContract<VirtualKukaController, VirtualKukaState>
{
    /// <inheritdoc/>
    protected override async Task<VirtualKukaController> StartAsync()
    {
        var controller = new VirtualKukaController(new VirtualKukaControllerOptions());
        await controller.StartAsync().WaitAsync(Long);
        return controller;
    }

    /// <inheritdoc/>
    protected override async Task<Robot> ConnectAsync(VirtualKukaController controller, Action<Robot>? configure = null) =>
        (await KukaTestSupport.ConnectKukaAsync(controller, configure)).Bot;

    /// <inheritdoc/>
    protected override string WriteOutput => "WriteDigital(2, true);";

    /// <inheritdoc/>
    protected override string OutputKey => "2";

    [Fact]
    public async Task Stop_WhenNothingRuns_ClosesTheLink_AndANewConnectionRuns()
    {
        await using VirtualKukaController controller = await StartAsync();
        Robot bot = await ConnectAsync(controller);
        try
        {
            bot.Do("SpeedTo(200); Move(0, 0, -10);");
            await bot.WaitForCompletionAsync().WaitAsync(Long);
            Vector at = controller.State.Position;

            // The driver waits for actions in its main loop: the interrupt answers the stop with nothing to fail or RESUME.
            await bot.StopAsync().WaitAsync(Long);
            Assert.False(bot.IsConnected);

            Robot again = await ConnectAsync(controller);
            try
            {
                again.Do("SpeedTo(200); Move(0, 0, 10);");
                await again.WaitForCompletionAsync().WaitAsync(Long);
                Assert.True(controller.State.Position.IsSimilar(at + new Vector(0, 0, 10), 1e-2), controller.State.Position.ToString());
            }
            finally
            {
                await again.DisconnectAsync();
            }
        }
        finally
        {
            await bot.DisconnectAsync();
        }
    }
}
