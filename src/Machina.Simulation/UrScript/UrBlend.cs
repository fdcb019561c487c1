namespace Machina.Simulation.UrScript;

/// <summary>
/// A blend the arm may make: the last motion returned when the arm entered the zone of its waypoint (<paramref name="Entry"/>, at
/// <paramref name="Speed"/> m/s; the motion's own speed <paramref name="Cruise"/>) and the next linear motion blends from there; anything else first lets the arm stop at the
/// <paramref name="Corner"/>. The radius is in m, the acceleration in m/s²; <paramref name="Thread"/> is the program thread that moved.
/// </summary>
internal sealed record UrBlend(Pose Entry, Pose Corner, Joints CornerJoints, double Radius, double Speed, double Cruise, double Acceleration, int Thread, int Line, string Function);
