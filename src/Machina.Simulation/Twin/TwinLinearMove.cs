namespace Machina.Simulation.Twin;

/// <summary>
/// A linear motion to <paramref name="Target"/> (TCP, base frame) at <paramref name="Joints"/>: <paramref name="Speed"/> m/s,
/// <paramref name="Acceleration"/> m/s², <paramref name="PlainSeconds"/> as it takes from rest to rest (the turn included), the
/// zone radius <paramref name="ZoneMm"/> in mm (0: a stop point) that it may end in when <paramref name="MayBlend"/>.
/// </summary>
internal readonly record struct TwinLinearMove(Pose Target, Joints Joints, double Speed, double Acceleration, double PlainSeconds, double ZoneMm, bool MayBlend);
