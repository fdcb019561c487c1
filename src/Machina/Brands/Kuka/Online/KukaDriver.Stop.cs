using System.Text;

namespace Machina;

internal sealed partial class KukaDriver
{
    /// <summary>Stop, pause and resume on the driver's channel and their answers (its interrupt brakes first, which takes a moment).</summary>
    private readonly ControlExchange _control;

    /// <inheritdoc/>
    /// <remarks>
    /// <c>&lt;PAUSE/&gt;</c> on the driver's channel sets $FLAG[5]; the driver's interrupt BRAKEs the motion where the arm is, answers
    /// <c>&lt;C K="1"/&gt;</c> and waits in its interrupt routine. <see cref="ResumeAsync"/> sends <c>&lt;RESUME/&gt;</c>: the motion goes on.
    /// </remarks>
    public Task PauseAsync(CancellationToken cancellationToken) => ControlAsync(KukaProtocol.PauseCommand, 1, "pause", cancellationToken);

    /// <inheritdoc/>
    public Task ResumeAsync(CancellationToken cancellationToken) => ControlAsync(KukaProtocol.ResumeCommand, 2, "resume", cancellationToken);

    /// <inheritdoc/>
    /// <remarks>
    /// <c>&lt;STOP/&gt;</c> on the driver's channel sets $FLAG[4]; the driver's interrupt BRAKEs the motion, fails the action under way
    /// (<c>&lt;F Code="7"/&gt;</c>), ends it with RESUME, drops everything else until the next connection and answers <c>&lt;C K="3"/&gt;</c>.
    /// </remarks>
    public Task StopMotionAsync(CancellationToken cancellationToken) => ControlAsync(KukaProtocol.StopCommand, 3, "stop", cancellationToken);

    /// <summary>Sends one command on the driver's channel and waits for its answer.</summary>
    private Task ControlAsync(string command, int answer, string what, CancellationToken cancellationToken) =>
        _control.RunAsync(() =>
            {
                TcpLink link = Link ?? throw new InvalidOperationException($"Cannot {what}: the link is not open.");
                link.Post(Encoding.ASCII.GetBytes(command));
            }, answer, what,
            $"The KUKA driver did not answer the {what} command within {Num.G(_control.Timeout.TotalSeconds)} s (is the machina_kuka_driver of this Machina loaded, with STOP, PAUSE and RESUME in machina_kuka_server.xml?).",
            cancellationToken);

    /// <summary>A <c>&lt;C K="n"/&gt;</c> from the driver: the command it answers is done.</summary>
    private void OnControl(int done)
    {
        if (!_control.Answer(done))
        {
            Log.Debug($"Ignored from the controller: <C K=\"{done}\"/>");
        }
    }

    /// <summary>The links close: a stop, pause or resume still waiting for its answer fails now (it cannot come any more).</summary>
    protected override void Closing() => _control.Abandon("KUKA driver");
}
