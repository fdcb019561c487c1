namespace Machina;

public sealed partial class Robot : IAsyncDisposable, IDisposable
{
    private volatile bool _disposed;

    /// <summary>
    /// Disconnects (actions sent but not confirmed stay unconfirmed), stops the robot's event loop at once (events not raised
    /// yet are dropped, and no handler runs after this returns) and refuses to go online again. Offline verbs keep working.
    /// </summary>
    public async ValueTask DisposeAsync()
    {
        if (_disposed)
        {
            return;
        }
        _disposed = true;
        OnlineSession? session = _session;
        if (session is not null)
        {
            await session.DisconnectAsync().ConfigureAwait(false);
            await session.CloseAsync(raiseQueued: false).ConfigureAwait(false);
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
