namespace Machina.Simulation.Twin;

/// <summary>
/// A corner the arm may round (<see cref="BlendModel"/>): the last linear motion returned to the program when the arm entered the
/// zone of its waypoint <paramref name="Corner"/> (at <paramref name="Entry"/>, moving at <paramref name="Speed"/> m/s); the next
/// linear motion blends from there, anything else first lets the arm stop at the waypoint. <paramref name="Radius"/> in m,
/// <paramref name="Acceleration"/> in m/s²; <paramref name="Line"/> and <paramref name="Text"/> name the motion.
/// </summary>
internal sealed record TwinBlend(Pose Entry, Pose Corner, Joints CornerJoints, double Radius, double Speed, double Acceleration, int Line, string Text);
