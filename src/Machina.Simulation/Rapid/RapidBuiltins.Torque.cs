namespace Machina.Simulation.Rapid;

/// <summary>
/// What programs read of the axes' motor torques: the function <c>GetMotorTorque([\MecUnit] AxisNo)</c> and the instruction
/// <c>GetJointData [\MechUnit] AxisNo [\Torque]</c> (OmniCore; the form pygofa's GoFa servers call). The twin has no dynamics
/// model: every axis of the arm reads 0 Nm, as a KRL twin's $TORQUE_AXIS_ACT does; an axis the arm does not have is an argument
/// error (ERR_AXIS_PAR) with the line, as for the controller's other axis numbers.
/// </summary>
internal static partial class RapidBuiltins
{
    /// <summary>The axes of the arm a twin moves.</summary>
    private const int ArmAxes = 6;

    private static IEnumerable<RapidBuiltin> Torque() =>
    [
        Function("GetMotorTorque", "num", [Opt("MecUnit", "mecunit"), P("AxisNo", "num")], call => AxisTorque(call, call.Num(1))),
        Instruction("GetJointData", [Opt("MechUnit", "mecunit"), P("AxisNo", "num"), Opt("Torque", "num", reference: true)], call =>
        {
            double torque = AxisTorque(call, call.Num(1));
            if (call.Has(2))
            {
                call.Set(2, torque);
            }
        }),
    ];

    /// <summary>The motor torque (Nm) of axis <paramref name="axis"/> of the arm: 0, the twin has no dynamics; another number is refused.</summary>
    private static double AxisTorque(RapidCall call, double axis) =>
        axis is >= 1 and <= ArmAxes && axis == Math.Floor(axis)
            ? 0.0
            : throw call.Error(RapidErrorNumbers.ByName["ERR_AXIS_PAR"], FormattableString.Invariant($"AxisNo {axis}: the mechanical unit has axes 1 to {ArmAxes}"));
}
