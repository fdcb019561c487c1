namespace Machina.Simulation;

public sealed partial class VirtualUrController
{
    /// <summary>Robot modes (client interfaces, RTDE robot_mode, dashboard robotmode): power off 3, idle 5, running 7.</summary>
    internal const int PowerOffMode = 3, IdleMode = 5, RunningMode = 7;

    private int _robotMode = RunningMode;
    private string? _loadedProgram;
    private string? _popup;
    private string? _operationalMode;
    private int _playingLoaded = -1;
    private double _speedSlider = 1;

    /// <summary>The speed slider (0–1): 1 until an RTDE client sets it (speed_slider_mask and speed_slider_fraction).</summary>
    public double SpeedSlider
    {
        get
        {
            lock (Gate)
            {
                return _speedSlider;
            }
        }
    }
    private readonly List<string> _userLog = [];

    /// <summary>
    /// The robot mode now: 7 running (the start: powered, brakes released, so that a script runs at once), 5 idle (powered,
    /// brakes held), 3 power off. The dashboard's and the primary interface's <c>power on</c>, <c>power off</c> and
    /// <c>brake release</c> (<c>set robotmode run</c>) change it.
    /// </summary>
    public int RobotMode
    {
        get
        {
            lock (Gate)
            {
                return _robotMode;
            }
        }
    }

    /// <summary>The program the dashboard loaded (<c>load NAME</c>), or null.</summary>
    public string? LoadedProgram
    {
        get
        {
            lock (Gate)
            {
                return _loadedProgram;
            }
        }
    }

    /// <summary>The popup the dashboard shows (<c>popup TEXT</c>) until <c>close popup</c>, or null.</summary>
    public string? Popup
    {
        get
        {
            lock (Gate)
            {
                return _popup;
            }
        }
    }

    /// <summary>The lines the dashboard added to the log (<c>addToLog</c>), oldest first (the last 1000).</summary>
    public IReadOnlyList<string> UserLog
    {
        get
        {
            lock (Gate)
            {
                return [.. _userLog];
            }
        }
    }

    /// <summary>Powers the arm off: the running program stops, as on a UR.</summary>
    private void PowerOff()
    {
        StopTwin(Twin);
        SetRobotMode(PowerOffMode);
    }

    /// <summary>Powers the arm on: idle (brakes held) from power off, unchanged when already on.</summary>
    private void PowerOn()
    {
        lock (Gate)
        {
            if (_robotMode == PowerOffMode)
            {
                _robotMode = IdleMode;
            }
        }
        WakeRtde();
    }

    /// <summary>Releases the brakes: running, from idle or power off (a UR powers on first).</summary>
    private void ReleaseBrakes() => SetRobotMode(RunningMode);

    private void SetRobotMode(int mode)
    {
        lock (Gate)
        {
            _robotMode = mode;
        }
        WakeRtde();
    }

    /// <summary>The robot mode's name as the dashboard gives it.</summary>
    private static string RobotModeName(int mode) => mode switch
    {
        PowerOffMode => "POWER_OFF",
        IdleMode => "IDLE",
        _ => "RUNNING",
    };
}
