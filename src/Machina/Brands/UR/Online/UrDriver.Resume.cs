namespace Machina;

internal sealed partial class UrDriver
{
    /// <summary>How long a resume waits for RTDE to show the program running again.</summary>
    private static readonly TimeSpan ResumeTimeout = TimeSpan.FromSeconds(10);

    /// <inheritdoc/>
    /// <remarks>
    /// Over the dashboard server: asks the safety status; after a protective stop closes the safety popup and unlocks it;
    /// then plays the paused driver program and completes when RTDE shows it running. An emergency stop must be released at
    /// the robot first.
    /// </remarks>
    public async Task ResumeAsync(CancellationToken cancellationToken)
    {
        await using (UrDashboard dashboard = await UrDashboard.OpenAsync(_host, _ports.Dashboard, cancellationToken).ConfigureAwait(false))
        {
            // Asked now, not read from the last RTDE package: the button may have been released a moment ago.
            string safety = await dashboard.CommandAsync("safetystatus", cancellationToken).ConfigureAwait(false);
            if (safety.StartsWith("could not understand", StringComparison.OrdinalIgnoreCase))
            {
                safety = await dashboard.CommandAsync("safetymode", cancellationToken).ConfigureAwait(false); // before software 5.4
            }
            if (safety.Contains("EMERGENCY", StringComparison.OrdinalIgnoreCase))
            {
                throw new RobotStoppedException("The UR robot is in an emergency stop: release the emergency stop button at the robot, then call Resume.", safety);
            }
            if (safety.Contains("PROTECTIVE", StringComparison.OrdinalIgnoreCase))
            {
                await dashboard.CommandAsync("close safety popup", cancellationToken).ConfigureAwait(false);
                string unlock = await dashboard.CommandAsync("unlock protective stop", cancellationToken).ConfigureAwait(false);
                if (!unlock.StartsWith("Protective stop releasing", StringComparison.OrdinalIgnoreCase))
                {
                    throw new RobotStoppedException($"The UR controller did not unlock the protective stop: \"{unlock}\".", unlock);
                }
            }
            string play = await dashboard.CommandAsync("play", cancellationToken).ConfigureAwait(false);
            if (!play.StartsWith("Starting program", StringComparison.OrdinalIgnoreCase))
            {
                throw new RobotStoppedException($"The UR controller did not play the driver program again: \"{play}\".", play);
            }
        }
        if (await WaitForSampleAsync(s => !s.IsSafetyStop && s.RuntimeState == RtdeSample.Playing, ResumeTimeout, cancellationToken).ConfigureAwait(false) is null)
        {
            throw new RobotStoppedException($"The UR controller accepted the resume but its program did not run again within {Num.G(ResumeTimeout.TotalSeconds)} s.");
        }
    }
}
