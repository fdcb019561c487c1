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
