namespace Machina;

/// <summary>Gets what a <see cref="TcpLink"/> receives. Calls come one at a time from the link's receive loop.</summary>
internal interface ILinkReceiver
{
    /// <summary>Bytes arrived; the span is only valid during the call.</summary>
    void OnReceived(ReadOnlySpan<byte> data);

    /// <summary>The connection ended: <paramref name="error"/> is null when the other side closed it cleanly. Not called after the link is disposed.</summary>
    void OnClosed(Exception? error);
}
