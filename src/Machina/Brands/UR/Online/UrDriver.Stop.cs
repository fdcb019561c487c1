namespace Machina;

internal sealed partial class UrDriver
{
    /// <inheritdoc/>
    /// <remarks>
    /// Dashboard <c>pause</c>: the controller holds the program, a motion in progress decelerates and stops on its path; RTDE
    /// then shows it paused. <see cref="ResumeAsync"/> plays it again and the motion goes on from where it stopped.
    /// </remarks>
    public Task PauseAsync(CancellationToken cancellationToken) =>
        DashboardAsync("pause", "Pausing program", RtdeSample.Paused, "pause", cancellationToken);

    /// <inheritdoc/>
    /// <remarks>
    /// Dashboard <c>stop</c>: the controller stops the driver program, a motion in progress decelerates and stops on its
    /// path, and nothing after it runs; it answers "Stopped" once it did. The program's end closes the driver's socket, so
    /// RTDE is not waited for. The driver program must be started again (connect again).
    /// </remarks>
    public Task StopMotionAsync(CancellationToken cancellationToken) =>
        DashboardAsync("stop", "Stopped", null, "stop", cancellationToken);

    /// <summary>Sends one dashboard command, checks its answer and waits until RTDE shows the runtime state it leads to.</summary>
    private async Task DashboardAsync(string command, string answer, uint? runtimeState, string what, CancellationToken cancellationToken)
    {
        await using (UrDashboard dashboard = await UrDashboard.OpenAsync(_host, _ports.Dashboard, cancellationToken).ConfigureAwait(false))
        {
            string reply = await dashboard.CommandAsync(command, cancellationToken).ConfigureAwait(false);
            if (!reply.StartsWith(answer, StringComparison.OrdinalIgnoreCase))
            {
                throw new RobotStoppedException($"The UR controller did not {what} the driver program: \"{reply}\".", reply);
            }
        }
        if (runtimeState is uint state
            && await WaitForSampleAsync(s => s.RuntimeState == state, ResumeTimeout, cancellationToken).ConfigureAwait(false) is null)
        {
            throw new RobotStoppedException($"The UR controller accepted \"{command}\" but RTDE did not show its program {(state == RtdeSample.Paused ? "paused" : "stopped")} within {Num.G(ResumeTimeout.TotalSeconds)} s.");
        }
    }
}
