namespace Machina;

public sealed partial class Robot
{
    /// <summary>
    /// Online: stops the motion now on the controller (UR: dashboard <c>stop</c>; ABB: the monitor task's StopMove, then the
    /// driver's interrupt clears the path), out of band, even while a move runs: the
    /// arm stops where it is, the action it was running fails and every action after it, sent or not, is cancelled
    /// (<see cref="ActionFailed"/>, reason "stopped by the user", code "stopped"). The link closes; connect again to go on
    /// from where the arm stopped. Completes once the controller stopped.
    /// </summary>
    /// <exception cref="InvalidOperationException">The robot is offline or not connected.</exception>
    /// <exception cref="NotSupportedException">The controller's driver cannot stop a motion from outside.</exception>
    /// <exception cref="MachinaException">The controller refused or could not be reached.</exception>
    public Task StopAsync(CancellationToken cancellationToken = default)
    {
        ThrowIfDisposed("stop");
        return RequireSession("stop").StopAsync(cancellationToken);
    }

    /// <summary>Same as <see cref="StopAsync"/>, waiting for it.</summary>
    /// <returns>True once the controller stopped.</returns>
    public bool Stop()
    {
        StopAsync().GetAwaiter().GetResult();
        return true;
    }

    /// <summary>
    /// Online: holds the motion on the controller (UR: dashboard <c>pause</c>; ABB: StopMove in the monitor task), out of band: a move in progress stops on its
    /// path and nothing more runs or is sent; <see cref="ControllerStopped"/> reports it. <see cref="Resume"/> goes on where
    /// it stopped, each action running once.
    /// </summary>
    /// <exception cref="InvalidOperationException">The robot is offline, not connected, or already stopped.</exception>
    /// <exception cref="NotSupportedException">The controller's driver cannot pause.</exception>
    /// <exception cref="MachinaException">The controller refused or could not be reached.</exception>
    public Task PauseAsync(CancellationToken cancellationToken = default)
    {
        ThrowIfDisposed("pause");
        return RequireSession("pause").PauseAsync(cancellationToken);
    }

    /// <summary>Same as <see cref="PauseAsync"/>, waiting for it.</summary>
    /// <returns>True once the controller holds the motion.</returns>
    public bool Pause()
    {
        PauseAsync().GetAwaiter().GetResult();
        return true;
    }
}
