using System.Net.Sockets;
using System.Text;

namespace Machina;

/// <summary>
/// A short conversation with the UR dashboard server (port 29999): one text command per line, one line of answer each,
/// after a greeting line. Used to resume after a protective stop.
/// </summary>
internal sealed class UrDashboard : IAsyncDisposable
{
    private readonly TcpClient _client;
    private readonly StreamReader _reader;
    private readonly Stream _stream;

    private UrDashboard(TcpClient client)
    {
        _client = client;
        _stream = client.GetStream();
        _reader = new StreamReader(_stream, Encoding.ASCII);
    }

    /// <summary>Connects and reads the greeting; throws <see cref="RobotConnectionException"/> when the dashboard cannot be reached.</summary>
    public static async Task<UrDashboard> OpenAsync(string host, int port, CancellationToken cancellationToken)
    {
        var client = new TcpClient { NoDelay = true };
        try
        {
            await client.ConnectAsync(host, port, cancellationToken).ConfigureAwait(false);
            var dashboard = new UrDashboard(client);
            await dashboard.ReadLineAsync(cancellationToken).ConfigureAwait(false);
            return dashboard;
        }
        catch (Exception ex) when (ex is SocketException or IOException)
        {
            client.Dispose();
            throw new RobotConnectionException($"Could not reach the UR dashboard server at {host}:{port}: {ex.Message}", ex);
        }
    }

    /// <summary>Sends one command and returns its one-line answer.</summary>
    public async Task<string> CommandAsync(string command, CancellationToken cancellationToken)
    {
        try
        {
            await _stream.WriteAsync(Encoding.ASCII.GetBytes(command + "\n"), cancellationToken).ConfigureAwait(false);
            return await ReadLineAsync(cancellationToken).ConfigureAwait(false);
        }
        catch (Exception ex) when (ex is SocketException or IOException)
        {
            throw new RobotConnectionException($"The UR dashboard server failed during \"{command}\": {ex.Message}", ex);
        }
    }

    private async Task<string> ReadLineAsync(CancellationToken cancellationToken) =>
        await _reader.ReadLineAsync(cancellationToken).ConfigureAwait(false)
            ?? throw new RobotConnectionException("The UR dashboard server closed the connection.");

    /// <inheritdoc/>
    public ValueTask DisposeAsync()
    {
        _reader.Dispose();
        _client.Dispose();
        return ValueTask.CompletedTask;
    }
}
