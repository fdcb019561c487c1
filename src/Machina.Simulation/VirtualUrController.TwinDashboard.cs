using Machina.Simulation.UrScript;

namespace Machina.Simulation;

public sealed partial class VirtualUrController
{
    /// <summary>
    /// A UR's stop: the arm stands where the motion had brought it, and the program ends (<see cref="UrTwinController.StopOnPathAsync"/>):
    /// awaited, so the thread-pool thread that serves the command waits for neither.
    /// </summary>
    private static Task StopTwinAsync(UrTwinController twin, CancellationToken token) => twin.StopOnPathAsync(token);

    /// <summary>
    /// The dashboard's answer to one command line, worded as UR's e-Series dashboard server words it, with the controller's state
    /// behind it: robot mode (power off, idle, running), the loaded program, play, pause and stop of the interpreter's program,
    /// safety, popups and the log. Commands are matched without regard to letter case, as a UR does.
    /// </summary>
    private async ValueTask<string> TwinDashboardAsync(UrTwinController twin, string command, CancellationToken token)
    {
        if (UserRoleCommand(command) is string roleAnswer)
        {
            return roleAnswer;
        }
        foreach (string prefixed in (string[])["load installation", "set operational mode", "generate flight report", "generate support file", "load", "popup", "addToLog"])
        {
            if (command.StartsWith(prefixed, StringComparison.OrdinalIgnoreCase) && (command.Length == prefixed.Length || command[prefixed.Length] == ' '))
            {
                return await DashboardWithArgumentAsync(prefixed, command[prefixed.Length..].Trim(), token).ConfigureAwait(false);
            }
        }
        bool running = twin.State == UrProgramState.Running;
        switch (command.ToLowerInvariant())
        {
            case "stop":
                await StopTwinAsync(twin, token).ConfigureAwait(false);
                return "Stopped";
            case "play":
                return await PlayAsync(twin, token).ConfigureAwait(false) ? "Starting program" : "Failed to execute: play";
            case "pause":
                if (running && HoldTwin())
                {
                    // Answered once the arm stands: the program's thread records where the hold stopped the motion at once. Awaited:
                    // the dashboard's connection is served on thread-pool threads, which must not block.
                    await twin.WaitUntilStandingAsync(TimeSpan.FromSeconds(5), token).ConfigureAwait(false);
                    WakeRtde();
                    return "Pausing program";
                }
                return "Failed to execute: pause";
            case "unlock protective stop":
                return UnlockProtectiveStop();
            case "close safety popup":
                return "closing safety popup";
            case "close popup":
                lock (Gate)
                {
                    _popup = null;
                }
                twin.ClosePopup(); // a program's popup too: a blocking one lets the program go on
                return "closing popup";
            case "quit":
                return "Disconnected";
            case "shutdown":
                await PowerOffAsync(token).ConfigureAwait(false);
                return "Shutting down";
            case "power on":
                PowerOn();
                return "Powering on";
            case "power off":
                await PowerOffAsync(token).ConfigureAwait(false);
                return "Powering off";
            case "brake release":
                ReleaseBrakes();
                return "Brake releasing";
            case "restart safety":
                ReleaseEmergencyStop();
                lock (Gate)
                {
                    _safety = Normal;
                }
                await PowerOffAsync(token).ConfigureAwait(false);
                return "Restarting safety";
            case "robotmode":
                return "Robotmode: " + RobotModeName(RobotMode);
            case "get robot model":
                return DashboardModelName;
            case "get serial number":
                return SerialNumber;
            case "polyscopeversion":
                return DashboardSoftware;
            case "version":
                Version v = SoftwareVersion;
                return $"{v.Major}.{v.Minor}.{Math.Max(v.Build, 0)}.{Math.Max(v.Revision, 0)}";
            case "get loaded program":
                return LoadedProgram is string loaded ? "Loaded program: " + loaded : "No program loaded";
            case "isprogramsaved":
                return "true " + (LoadedProgram ?? "<unnamed>");
            case "is in remote control":
                return "true";
            case "get operational mode":
                lock (Gate)
                {
                    return _operationalMode ?? "NONE";
                }
            case "clear operational mode":
                lock (Gate)
                {
                    _operationalMode = null;
                }
                return "No longer controlling the operational mode. Current operational mode: 'AUTOMATIC'.";
            case "savelog":
                return "Log saved to disk";
            case "programstate":
                return (!running ? "STOPPED" : TwinHeld ? "PAUSED" : "PLAYING") + " " + ProgramStateName(twin);
            case "running":
                return "Program running: " + (running && !TwinHeld ? "true" : "false");
            case "safetystatus" or "safetymode":
                string name = SafetyStatus switch { ProtectiveStopped => "PROTECTIVE_STOP", RobotEmergencyStopped => "ROBOT_EMERGENCY_STOP", _ => "NORMAL" };
                return (command.Equals("safetystatus", StringComparison.OrdinalIgnoreCase) ? "Safetystatus: " : "Safetymode: ") + name;
            default:
                return $"could not understand: '{command}'";
        }
    }

    /// <summary>The answer to a dashboard command that takes an argument (the text after the command).</summary>
    private async ValueTask<string> DashboardWithArgumentAsync(string command, string argument, CancellationToken token)
    {
        switch (command)
        {
            case "load":
                if (!argument.EndsWith(".urp", StringComparison.OrdinalIgnoreCase))
                {
                    return "File not found: " + argument;
                }
                await StopTwinAsync(Twin, token).ConfigureAwait(false);
                lock (Gate)
                {
                    _loadedProgram = argument;
                    _playingLoaded = Twin.ProgramsStarted; // the program now is the loaded one, until a script arrives
                }
                return "Loading program: " + argument;
            case "load installation":
                return argument.Length == 0 ? "File not found: " : "Loading installation: " + argument;
            case "popup":
                lock (Gate)
                {
                    _popup = argument;
                }
                return "showing popup";
            case "addToLog":
                if (argument.Length == 0)
                {
                    return "No log message to add";
                }
                lock (Gate)
                {
                    _userLog.Add(argument);
                    if (_userLog.Count > MaxKeptTexts)
                    {
                        _userLog.RemoveAt(0);
                    }
                }
                Pendant(argument);
                return "Added log message";
            case "set operational mode":
                string mode = argument.ToUpperInvariant();
                if (mode is not ("MANUAL" or "AUTOMATIC"))
                {
                    return "Failed setting operational mode. Please specify manual or automatic";
                }
                lock (Gate)
                {
                    _operationalMode = mode;
                }
                return $"Operational mode {mode} is set";
            case "generate flight report":
                // Asked for by UR's client library (software 3.13 / 5.8 on): answered as a UR answers; the twin writes no report.
                return "Flight Report generated with id: " + Interlocked.Increment(ref _flightReports).ToString(System.Globalization.CultureInfo.InvariantCulture);
            case "generate support file":
                // As the flight report: the answer a UR gives once the file is in the directory asked for; the twin writes none.
                return "Completed successfully: " + argument;
            default:
                return $"could not understand: '{command} {argument}'";
        }
    }

    /// <summary>
    /// Dashboard play: releases a paused program, or starts the loaded program when none runs. A .urp program is a PolyScope
    /// program the twin cannot read: it runs in its place a program that waits until stopped (approximated). Refused unless the
    /// arm is running (brakes released) and safe.
    /// </summary>
    private async ValueTask<bool> PlayAsync(UrTwinController twin, CancellationToken token)
    {
        if (RobotMode != RunningMode || SafetyStatus != Normal)
        {
            return false;
        }
        if (twin.State == UrProgramState.Running)
        {
            return ReleaseTwin();
        }
        string? loaded = LoadedProgram;
        if (loaded is null)
        {
            return false;
        }
        bool started = await twin.StartAsync("def loaded_program():\n  while True:\n    sleep(1)\n  end\nend\n", token).ConfigureAwait(false);
        if (started)
        {
            lock (Gate)
            {
                _playingLoaded = twin.ProgramsStarted;
            }
        }
        return started;
    }

    /// <summary>The program programState names: the loaded one while it plays, else the last script's name.</summary>
    private string ProgramStateName(UrTwinController twin)
    {
        lock (Gate)
        {
            if (_loadedProgram is not null && (_playingLoaded == twin.ProgramsStarted || twin.ProgramsStarted == 0))
            {
                // The program's file name, without the folders it was loaded from ("load /programs/a/b.urp": "STOPPED b.urp"),
                // as URSim gives it: UR's client library waits for "STOPPED " and the file name after loading a path.
                return _loadedProgram[(_loadedProgram.LastIndexOf('/') + 1)..];
            }
        }
        return twin.ProgramsStarted == 0 ? "<unnamed>" : twin.ProgramName ?? "<unnamed>";
    }

    /// <summary>How many flight reports the dashboard has been asked for: the id of the last one.</summary>
    private int _flightReports;

    /// <summary>The serial number the dashboard gives (UR's begin with the year of make).</summary>
    private const string SerialNumber = "20245500001";

    /// <summary>The arm's name as a UR dashboard gives it (<c>get robot model</c>): without the e-Series "e" ("UR5" for a UR5e).</summary>
    private string DashboardModelName
    {
        get
        {
            string name = (Model ?? RobotModels.Get("UR5e")).Name;
            return name.EndsWith('e') ? name[..^1] : name;
        }
    }

    /// <summary>
    /// The software version a UR dashboard gives (<c>PolyscopeVersion</c>): the configured controller version for an e-Series
    /// arm, 3.15 for a CB-Series arm (UR3, UR5, UR10), which never runs software 5.
    /// </summary>
    private string DashboardSoftware
    {
        get
        {
            Version v = SoftwareVersion;
            return $"URSoftware {v.Major}.{v.Minor}.{Math.Max(v.Build, 0)}.{Math.Max(v.Revision, 0)} (virtual controller)";
        }
    }

    /// <summary>The software version the controller reports everywhere: the configured one for an e-Series arm, 3.15.8 for a CB-Series arm (UR3, UR5, UR10), which never runs software 5.</summary>
    private Version SoftwareVersion
    {
        get
        {
            string name = (Model ?? RobotModels.Get("UR5e")).Name;
            bool cbSeries = !name.EndsWith('e') && RobotModels.Find(name + "e") is not null;
            return cbSeries ? new Version(3, 15, 8) : _options.ControllerVersion;
        }
    }
}
