using System.Net.Sockets;

namespace Machina.Simulation;

public sealed partial class VirtualUrController
{
    private readonly List<string> _scripts = [];
    private readonly List<NetworkStream> _scriptStreams = [];

    /// <summary>How many programs arrived on the script ports (each complete <c>def … end</c> or one-line program).</summary>
    public int ScriptsReceived
    {
        get
        {
            lock (Gate)
            {
                return _scripts.Count;
            }
        }
    }

    /// <summary>The last program received, or null.</summary>
    public string? LastScript
    {
        get
        {
            lock (Gate)
            {
                return _scripts.Count == 0 ? null : _scripts[^1];
            }
        }
    }

    private Task AcceptScriptsAsync(TcpListener listener, CancellationToken token) => AcceptAsync(listener, ReadScriptsAsync, token);

    /// <summary>
    /// Feeds what one connection to a script port sends to the interpreter, which starts each program when it is complete (the
    /// script manual's rules); runtime errors go back to every connection on the script ports.
    /// </summary>
    private async Task ReadScriptsAsync(TcpClient client, CancellationToken token)
    {
        var stream = client.GetStream();
        lock (Gate)
        {
            _scriptStreams.Add(stream);
        }
        try
        {
            await FeedTwinAsync(stream, Twin, token).ConfigureAwait(false);
        }
        finally
        {
            lock (Gate)
            {
                _scriptStreams.Remove(stream);
            }
        }
    }
}
