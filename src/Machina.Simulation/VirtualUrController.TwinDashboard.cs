using Machina.Simulation.UrScript;

namespace Machina.Simulation;

public sealed partial class VirtualUrController
{
    /// <summary>
    /// A UR's stop decelerates the arm on its path and ends the program: the twin holds its motion first, so the arm stands
    /// where the motion had brought it (not back at the motion's start), then ends the program and clears the hold.
    /// </summary>
    private static void StopTwin(UrTwinController twin)
    {
        if (twin.State == UrProgramState.Running && twin.Hold())
        {
            // The program's thread records where the arm stands when the hold reaches the motion (bounded: it does at once).
            SpinWait.SpinUntil(() => twin.Motion is null, TimeSpan.FromSeconds(5));
            twin.StopProgram();
            twin.Release();
            return;
        }
        twin.StopProgram();
    }

    /// <summary>The dashboard answers about the interpreter's program (the commands a host uses): play and pause release and hold the program at its next read.</summary>
    private string TwinDashboard(UrTwinController twin, string command)
    {
        bool running = twin.State == UrProgramState.Running;
        switch (command)
        {
            case "stop":
                StopTwin(twin);
                return "Stopped";
            case "play":
                return running && SafetyStatus == Normal && ReleaseTwin() ? "Starting program" : "Failed to execute: play";
            case "pause":
                if (running && HoldTwin())
                {
                    // Answered once the arm stands: the program's thread records where the hold stopped the motion at once.
                    SpinWait.SpinUntil(() => twin.Motion is null, TimeSpan.FromSeconds(5));
                    WakeRtde();
                    return "Pausing program";
                }
                return "Failed to execute: pause";
            case "unlock protective stop":
                return UnlockProtectiveStop();
            case "close safety popup":
                return "closing safety popup";
            case "quit":
                return "Disconnected";
            case "robotmode":
                return "Robotmode: RUNNING";
            case "get robot model":
                return DashboardModelName;
            case "PolyscopeVersion":
                return DashboardSoftware;
            case "programState":
                return (!running ? "STOPPED" : TwinHeld ? "PAUSED" : "PLAYING") + (twin.ProgramsStarted == 0 ? " <unnamed>" : " " + (twin.ProgramName ?? "<unnamed>"));
            case "running":
                return "Program running: " + (running && !TwinHeld ? "true" : "false");
            case "safetystatus" or "safetymode":
                string name = SafetyStatus switch { ProtectiveStopped => "PROTECTIVE_STOP", RobotEmergencyStopped => "ROBOT_EMERGENCY_STOP", _ => "NORMAL" };
                return (command == "safetystatus" ? "Safetystatus: " : "Safetymode: ") + name;
            default:
                return $"could not understand: '{command}'";
        }
    }

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
            string name = (Model ?? RobotModels.Get("UR5e")).Name;
            bool cbSeries = !name.EndsWith('e') && RobotModels.Find(name + "e") is not null;
            Version v = cbSeries ? new Version(3, 15, 8) : _options.ControllerVersion;
            return $"URSoftware {v.Major}.{v.Minor}.{Math.Max(v.Build, 0)}.0 (virtual controller)";
        }
    }
}
