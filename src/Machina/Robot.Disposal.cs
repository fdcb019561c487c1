namespace Machina;

public sealed partial class Robot : IAsyncDisposable, IDisposable
{
    private volatile bool _disposed;

    /// <summary>
    /// Disconnects (actions sent but not confirmed stay unconfirmed), stops the robot's event loop at once (events not raised
    /// yet are dropped, and no handler runs after this returns). From then on the robot refuses everything: every verb,
    /// Connect (a connection under way ends disconnected), Resume, WaitForCompletion and ControlMode throw
    /// <see cref="ObjectDisposedException"/>; a call waiting for completion fails with it.
    /// </summary>
    public async ValueTask DisposeAsync()
    {
        OnlineSession? session;
        lock (_issueLock)
        {
            // Under the issue lock: no action is accepted once this is set, and no session is created after it is read.
            if (_disposed)
            {
                return;
            }
            _disposed = true;
            session = _session;
        }
        if (session is not null)
        {
            await session.DisposeAsync().ConfigureAwait(false);
        }
    }

    /// <summary>Same as <see cref="DisposeAsync"/>, waiting for it.</summary>
    public void Dispose() => DisposeAsync().AsTask().GetAwaiter().GetResult();

    private void ThrowIfDisposed(string what)
    {
        if (_disposed)
        {
            throw new ObjectDisposedException(Name, $"Cannot {what}: the robot \"{Name}\" was disposed. Create a new robot.");
        }
    }
}
