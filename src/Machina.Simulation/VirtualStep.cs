namespace Machina.Simulation;

/// <summary>What executing one instruction does: the state after it, how long it takes in robot seconds, and whether it moves in joint space.</summary>
/// <param name="State">The state once the instruction is done.</param>
/// <param name="Seconds">Duration in real robot seconds, before the speed factor; 0 for an instant setting.</param>
/// <param name="InJointSpace">True for a joint move (joints interpolated), false for a linear move or no motion.</param>
internal readonly record struct VirtualStep(VirtualRobotState State, double Seconds, bool InJointSpace = false);

/// <summary>Thrown by a brand's planner for an instruction the simulated robot cannot execute; the controller logs it and keeps serving.</summary>
internal sealed class VirtualRefusalException(string message) : Exception(message);
