using Machina.Simulation.UrScript;

namespace Machina.Simulation;

public sealed partial class VirtualUrController
{
    /// <summary>The output integer register Machina's driver writes its instance number to (docs/protocol-ur.md).</summary>
    private const int InstanceRegisterNumber = 26;

    /// <summary>The dashboard answers about the interpreter's program (the commands a host uses; play and pause are not modelled).</summary>
    private static string TwinDashboard(UrTwinController twin, string command)
    {
        bool running = twin.State == UrProgramState.Running;
        switch (command)
        {
            case "stop":
                twin.StopProgram();
                return "Stopped";
            case "play" or "pause":
                return "Failed to execute: " + command;
            case "unlock protective stop":
                return "Protective stop releasing";
            case "close safety popup":
                return "closing safety popup";
            case "quit":
                return "Disconnected";
            case "robotmode":
                return "Robotmode: RUNNING";
            case "programState":
                return (running ? "PLAYING" : "STOPPED") + (twin.ProgramsStarted == 0 ? " <unnamed>" : " " + (twin.ProgramName ?? "<unnamed>"));
            case "running":
                return "Program running: " + (running ? "true" : "false");
            case "safetystatus":
                return "Safetystatus: NORMAL";
            case "safetymode":
                return "Safetymode: NORMAL";
            default:
                return $"could not understand: '{command}'";
        }
    }
}
