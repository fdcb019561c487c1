namespace Machina.Simulation;

public sealed partial class VirtualUrController
{
    /// <summary>Robot modes (client interfaces, RTDE robot_mode, dashboard robotmode): power off 3, idle 5, running 7.</summary>
    internal const int PowerOffMode = 3, IdleMode = 5, RunningMode = 7;

    private int _robotMode;
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
    /// The robot mode now: 7 running (powered, brakes released: the start, so that a script runs at once, unless
    /// <see cref="VirtualUrControllerOptions.StartsPoweredOff"/>), 5 idle (powered, brakes held), 3 power off. The dashboard's
    /// and the primary interface's <c>power on</c>, <c>power off</c> and <c>brake release</c> (<c>set robotmode run</c>)
    /// change it. Programs run only while it is 7.
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

    /// <summary>Powers the arm off: the running program stops, as on a UR (awaited: no thread waits for it).</summary>
    private async Task PowerOffAsync(CancellationToken token)
    {
        await StopTwinAsync(Twin, token).ConfigureAwait(false);
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

    /// <summary>
    /// Why a program that arrives cannot start now, or null when it can: a UR runs programs only with the arm powered and its
    /// brakes released (robot mode running). The wording is the twin's: UR's manuals do not give the controller's.
    /// </summary>
    private string? StartRefusal()
    {
        int mode = RobotMode;
        return mode == RunningMode ? null
            : $"{NotReadyPrefix}the robot is {RobotModeName(mode)}: power it on and release the brakes (dashboard \"power on\", \"brake release\") before a program runs";
    }

    /// <summary>How the refusal of a program while the arm is not running starts (see <see cref="StartRefusal"/>).</summary>
    internal const string NotReadyPrefix = "Program refused: ";

    /// <summary>The robot mode's name as the dashboard gives it.</summary>
    private static string RobotModeName(int mode) => mode switch
    {
        PowerOffMode => "POWER_OFF",
        IdleMode => "IDLE",
        _ => "RUNNING",
    };
}
