using System.Net.Sockets;

namespace Machina.Simulation;

public abstract partial class VirtualController<TState>
{
    /// <summary>
    /// Serves driver clients one at a time, as a driver program does: each is greeted and made the driver connection
    /// (<see cref="AttachClientAsync"/>), read by <paramref name="read"/> until it leaves, then dropped; the next one is
    /// accepted only then, so whatever a client sent is buffered before the next greeting reports the progress.
    /// </summary>
    private protected async Task ServeDriverClientsAsync(
        TcpListener listener, Func<NetworkStream, CancellationToken, Task> greet, Func<NetworkStream, CancellationToken, Task> read, CancellationToken token)
    {
        while (await AcceptAsync(listener, token).ConfigureAwait(false) is TcpClient client)
        {
            if (await AttachClientAsync(client, greet, token).ConfigureAwait(false))
            {
                await read(client.GetStream(), token).ConfigureAwait(false);
                DropClient(client);
            }
        }
    }

    /// <summary>Serves clients of a second channel (a monitor) one at a time with <paramref name="serve"/>, closing each after it.</summary>
    private protected static async Task ServeClientsAsync(TcpListener listener, Func<NetworkStream, CancellationToken, Task> serve, CancellationToken token)
    {
        while (await AcceptAsync(listener, token).ConfigureAwait(false) is TcpClient client)
        {
            using (client)
            {
                await serve(client.GetStream(), token).ConfigureAwait(false);
            }
        }
    }

    /// <summary>The next client (with Nagle off), or null once the controller stops.</summary>
    private static async Task<TcpClient?> AcceptAsync(TcpListener listener, CancellationToken token)
    {
        if (token.IsCancellationRequested)
        {
            return null;
        }
        try
        {
            TcpClient client = await listener.AcceptTcpClientAsync(token).ConfigureAwait(false);
            client.NoDelay = true;
            return client;
        }
        catch (Exception e) when (e is OperationCanceledException or SocketException or ObjectDisposedException or InvalidOperationException)
        {
            return null;
        }
    }
}
