using Machina.Simulation.UrScript;

namespace Machina.Simulation;

public sealed partial class VirtualUrController
{
    /// <summary>The dashboard answers about the interpreter's program (the commands a host uses): play and pause release and hold the program at its next read.</summary>
    private string TwinDashboard(UrTwinController twin, string command)
    {
        bool running = twin.State == UrProgramState.Running;
        switch (command)
        {
            case "stop":
                twin.StopProgram();
                return "Stopped";
            case "play":
                return running && SafetyStatus == Normal && ReleaseTwin() ? "Starting program" : "Failed to execute: play";
            case "pause":
                if (running && HoldTwin())
                {
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
}
