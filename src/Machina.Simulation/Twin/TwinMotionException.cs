namespace Machina.Simulation.Twin;

/// <summary>A motion the arm cannot do (unreachable target, joint limit, bad speed): the controller stops the program.</summary>
internal sealed class TwinMotionException(string message) : Exception(message);
