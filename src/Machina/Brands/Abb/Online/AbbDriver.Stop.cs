namespace Machina;

internal sealed partial class AbbDriver
{
    /// <summary>Out-of-band commands to the monitor task and their answers (it looks for commands between two state reports).</summary>
    private readonly ControlExchange _control;

    /// <inheritdoc/>
    /// <remarks>
    /// "P" on the monitor connection: the monitor task runs <c>StopMove \AllMotionTasks</c>, the motion holds on its path where
    /// the arm is, and answers <c>$28 1;</c>. <see cref="ResumeAsync"/> sends "R" (<c>StartMove</c>): the held move goes on.
    /// </remarks>
    public Task PauseAsync(CancellationToken cancellationToken) => ControlAsync('P', 1, "pause", cancellationToken);

    /// <inheritdoc/>
    public Task ResumeAsync(CancellationToken cancellationToken) => ControlAsync('R', 2, "resume", cancellationToken);

    /// <inheritdoc/>
    /// <remarks>
    /// "S" on the monitor connection: the monitor task holds the motion (<c>StopMove \AllMotionTasks</c>), sets the persistent
    /// <c>machinaStopRequest</c> and answers <c>$28 3;</c>; the driver's interrupt on it clears the path, fails the request under
    /// way (<c>$26 id 4;</c>) and drops the rest until the host connects again.
    /// </remarks>
    public Task StopMotionAsync(CancellationToken cancellationToken) => ControlAsync('S', 3, "stop", cancellationToken);

    /// <summary>Sends one command to the monitor task and waits for its answer.</summary>
    private Task ControlAsync(char command, int answer, string what, CancellationToken cancellationToken)
    {
        TcpLink monitor = _monitor ?? throw new NotSupportedException(
            $"Cannot {what} this ABB robot: its monitor task is not running (the controller needs the Multitasking option and machina_abb_monitor on the next port).");
        return _control.RunAsync(() => monitor.Post([(byte)command]), answer, what,
            $"The ABB monitor task did not answer the {what} command within {Num.G(_control.Timeout.TotalSeconds)} s (is machina_abb_monitor 1.6 or later loaded?).",
            cancellationToken);
    }

    /// <summary>A <c>$28 n;</c> from the monitor task: the command it answers is done.</summary>
    private void OnControl(int done)
    {
        if (!_control.Answer(done))
        {
            Log.Debug($"Ignored from the monitor: $28 {done};");
        }
    }

    /// <summary>The links close: a stop, pause or resume still waiting for its answer fails now (it cannot come any more).</summary>
    protected override void Closing() => _control.Abandon("ABB monitor task");
}
