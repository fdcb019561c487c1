namespace Machina;

internal sealed partial class OnlineSession
{
    /// <summary>Set once the robot is disposed: the session refuses everything from then on, and a connect under way ends disconnected.</summary>
    private volatile bool _disposed;

    /// <summary>
    /// Disposes the session for good: closes the link, fails a waiting call with <see cref="ObjectDisposedException"/>, stops the
    /// event loop at once (queued events are dropped). A connection under way is closed when its handshake ends.
    /// </summary>
    internal async Task DisposeAsync()
    {
        (Connection? link, List<(string What, TaskCompletionSource Signal)> waiters) = await AskAsync(() =>
        {
            _disposed = true;
            List<(string What, TaskCompletionSource Signal)> waiting = TakeWaiters();
            FailReadWaiters(Disposed("read an input"), direct: true);   // the event pump stops below: signal them here
            Connection? current = _link;
            if (current is not null)
            {
                Detach(new RobotConnectionException($"The robot \"{_host.Name}\" was disposed."));   // the waiter was taken above
            }
            return (current, waiting);
        }).ConfigureAwait(false);
        foreach ((string what, TaskCompletionSource signal) in waiters)
        {
            signal.TrySetException(Disposed(what));
        }
        if (link is not null)
        {
            await CloseQuietlyAsync(link.Driver).ConfigureAwait(false);
            _host.Logger.Info($"Disconnected from {_host.Brand} robot \"{_host.Name}\" (disposed).");
        }
        await _events.StopAsync(raiseQueued: false).ConfigureAwait(false);
    }

    /// <summary>The exception a disposed robot throws for <paramref name="what"/>.</summary>
    private ObjectDisposedException Disposed(string what) =>
        new(_host.Name, $"Cannot {what}: the robot \"{_host.Name}\" was disposed. Create a new robot.");
}
