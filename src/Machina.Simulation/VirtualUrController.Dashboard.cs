using System.Net.Sockets;
using System.Text;
using Machina.Simulation.Twin;

namespace Machina.Simulation;

public sealed partial class VirtualUrController
{
    private readonly List<string> _dashboardCommands = [];

    /// <summary>The dashboard commands received so far, in order (the last 1000).</summary>
    public IReadOnlyList<string> DashboardCommands
    {
        get
        {
            lock (Gate)
            {
                return [.. _dashboardCommands];
            }
        }
    }

    private Task AcceptDashboardClientsAsync(CancellationToken token) => AcceptAsync(_dashboardListener!, ServeDashboardAsync, token);

    /// <summary>The dashboard server: a greeting, then one answer line per command line.</summary>
    private async Task ServeDashboardAsync(TcpClient client, CancellationToken token)
    {
        var stream = client.GetStream();
        var reader = new TwinLineReader(stream, MaxDashboardLine);
        await stream.WriteAsync(Encoding.ASCII.GetBytes("Connected: Universal Robots Dashboard Server\n"), token).ConfigureAwait(false);
        while (await ReadDashboardLineAsync(reader, stream, token).ConfigureAwait(false) is string line)
        {
            string command = line.Trim();
            lock (Gate)
            {
                _dashboardCommands.Add(command);
                if (_dashboardCommands.Count > MaxKeptTexts)
                {
                    _dashboardCommands.RemoveAt(0);
                }
            }
            string answer = await TwinDashboardAsync(Twin, command, token).ConfigureAwait(false);
            await stream.WriteAsync(Encoding.ASCII.GetBytes(answer + "\n"), token).ConfigureAwait(false);
            if (command == "quit")
            {
                return;
            }
        }
    }

    /// <summary>The longest dashboard command line taken, in bytes (docs/simulation.md, Network limits).</summary>
    internal const int MaxDashboardLine = 4096;

    /// <summary>The next command line, or null when the client left or sent a line past the cap (answered, then closed).</summary>
    private static async Task<string?> ReadDashboardLineAsync(TwinLineReader reader, NetworkStream stream, CancellationToken token)
    {
        try
        {
            return await reader.ReadLineAsync(token).ConfigureAwait(false);
        }
        catch (InvalidDataException ex)
        {
            await stream.WriteAsync(Encoding.ASCII.GetBytes($"Refused: {ex.Message}; the dashboard server closes the connection\n"), token).ConfigureAwait(false);
            return null;
        }
    }
}
