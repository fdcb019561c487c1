namespace Machina;

internal sealed partial class AbbDriver
{
    /// <summary>The longest the host waits for the monitor to name the arm (a monitor from before "M" never answers).</summary>
    private static readonly TimeSpan RobotTypeTimeout = TimeSpan.FromSeconds(5);

    /// <summary>The monitor's answer to "M": the robot type, or null when it answered something else.</summary>
    private readonly TaskCompletionSource<string?> _robotType = new(TaskCreationOptions.RunContinuationsAsynchronously);

    /// <summary>
    /// Asks the monitor task which arm the controller runs ("M" on the monitor connection, answered <c>$@0 101 3 IRB 120-3/0.6;</c>
    /// from RAPID's <c>GetSysInfo(\RobotType)</c>) and adds the answer to <paramref name="handshake"/>. Out of band, so nothing
    /// changes in the driver's request stream. Never fails the connection: without a monitor, or without an answer within
    /// <paramref name="timeout"/> (at most 5 s; a monitor from before this question ignores it), there is no model.
    /// </summary>
    private async Task<DeviceHandshake> WithRobotTypeAsync(DeviceHandshake handshake, TimeSpan timeout, CancellationToken cancellationToken)
    {
        if (_monitor is not TcpLink monitor)
        {
            return handshake;
        }
        monitor.Post("M"u8);
        string? robotType;
        try
        {
            TimeSpan wait = timeout < RobotTypeTimeout ? timeout : RobotTypeTimeout;
            robotType = await _robotType.Task.WaitAsync(wait > TimeSpan.Zero ? wait : TimeSpan.Zero, Time, cancellationToken).ConfigureAwait(false);
        }
        catch (TimeoutException)
        {
            Log.Info("The ABB monitor task did not say which arm this is (machina_abb_monitor from before 1.6.0 gained the question); the robot keeps the model it has.");
            return handshake;
        }
        if (string.IsNullOrEmpty(robotType))
        {
            return handshake;
        }
        return handshake with { ModelName = robotType, Model = AbbRobotType.Find(robotType) };
    }

    /// <summary>A <c>$@0 101 p1 text;</c> from the monitor: the robot type when p1 is 3.</summary>
    private void OnInformation(in AbbMessage message)
    {
        string text = message.Text ?? "";
        string prefix = AbbRobotType.InformationCode.ToString(System.Globalization.CultureInfo.InvariantCulture) + " ";
        _robotType.TrySetResult(text.StartsWith(prefix, StringComparison.Ordinal) ? text[prefix.Length..].Trim() : null);
    }
}
