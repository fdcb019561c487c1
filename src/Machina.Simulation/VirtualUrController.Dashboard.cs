using System.Net.Sockets;
using System.Text;

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
        using var reader = new StreamReader(stream, Encoding.ASCII);
        await stream.WriteAsync(Encoding.ASCII.GetBytes("Connected: Universal Robots Dashboard Server\n"), token).ConfigureAwait(false);
        while (await reader.ReadLineAsync(token).ConfigureAwait(false) is string line)
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
            string answer = Dashboard(command);
            await stream.WriteAsync(Encoding.ASCII.GetBytes(answer + "\n"), token).ConfigureAwait(false);
            if (command == "quit")
            {
                return;
            }
        }
    }

    /// <summary>The answer of the dashboard server to one command (the commands a host uses).</summary>
    private string Dashboard(string command)
    {
        if (Twin is { } twin)
        {
            return TwinDashboard(twin, command);
        }
        switch (command)
        {
            case "play":
                return Play();
            case "pause":
                return Pause();
            case "stop":
                StopProgram("stopped from the dashboard");
                return "Stopped";
            case "unlock protective stop":
                return UnlockProtectiveStop();
            case "close safety popup":
                return "closing safety popup";
            case "quit":
                return "Disconnected";
            case "robotmode":
                return "Robotmode: RUNNING";
            case "programState":
                lock (Gate)
                {
                    string state = _runtime switch { Playing => "PLAYING", Paused => "PAUSED", _ => "STOPPED" };
                    return state + (_kind == DriverKind.None ? " <unnamed>" : " machina_ur_driver");
                }
            case "running":
                return "Program running: " + (RuntimeState == Playing ? "true" : "false");
            case "safetystatus" or "safetymode":
                string name = SafetyStatus switch { ProtectiveStopped => "PROTECTIVE_STOP", RobotEmergencyStopped => "ROBOT_EMERGENCY_STOP", _ => "NORMAL" };
                return (command == "safetystatus" ? "Safetystatus: " : "Safetymode: ") + name;
            default:
                return $"could not understand: '{command}'";
        }
    }
}
