using System.Globalization;
using Machina.Simulation.Twin;

namespace Machina.Simulation.Rapid;

/// <summary>
/// The YuMi SmartGripper's instructions and functions (Hand_Initialize, Hand_GripInward, Hand_GripOutward, Hand_MoveTo,
/// Hand_JogInward, Hand_JogOutward, Hand_Stop, Hand_SetMaxSpeed, Hand_SetHoldForce, Hand_WaitMovingCompleted, Hand_GetActualPos,
/// Hand_GetActualForce, Hand_IsCalibrated), on the task's <see cref="RapidHand"/>: the fingers travel at the maximum speed (the
/// instruction waits for them unless \NoWait), a move before calibration raises ERR_HAND_NOTCALIBRATED, a value beyond the
/// gripper's range ERR_ARGVALERR. Each finger move is traced where it ends.
/// </summary>
internal static partial class RapidBuiltins
{
    private static IEnumerable<RapidBuiltin> SmartGripper() =>
    [
        Instruction("Hand_Initialize", [Opt("maxSpd", "num"), Opt("holdForce", "num"), Opt("phyLimit", "num"), Sw("Calibrate"), Sw("Jog")], call =>
        {
            RapidHand hand = call.Machine.Task.Hand;
            hand.MaxSpeed = call.Has(0) ? InRange(call, "Hand_Initialize \\maxSpd", call.Num(0), RapidHand.SpeedLimit) : hand.MaxSpeed;
            hand.HoldForce = call.Has(1) ? InRange(call, "Hand_Initialize \\holdForce", call.Num(1), RapidHand.ForceLimit) : hand.HoldForce;
            hand.PhysicalLimit = call.Has(2) ? InRange(call, "Hand_Initialize \\phyLimit", call.Num(2), RapidHand.StrokeLimit) : hand.PhysicalLimit;
            if (call.Has(3) || call.Has(4))
            {
                // Calibration closes the fingers to their zero.
                FingersTo(call, "Hand_Initialize", 0, 0, wait: true);
                hand.Calibrated = true;
            }
        }),
        Instruction("Hand_GripInward", [Opt("holdForce", "num"), Opt("targetPos", "num"), Sw("NoWait")], call => Grip(call, "Hand_GripInward", inward: true)),
        Instruction("Hand_GripOutward", [Opt("holdForce", "num"), Opt("targetPos", "num"), Sw("NoWait")], call => Grip(call, "Hand_GripOutward", inward: false)),
        Instruction("Hand_MoveTo", [P("targetPos", "num"), Sw("NoWait")], call =>
        {
            RapidHand hand = Calibrated(call, "Hand_MoveTo");
            FingersTo(call, "Hand_MoveTo", InRange(call, "Hand_MoveTo", call.Num(0), hand.PhysicalLimit, zero: true), 0, wait: !call.Has(1));
        }),
        Instruction("Hand_JogInward", [], call => FingersTo(call, "Hand_JogInward", 0, 0, wait: false)),
        Instruction("Hand_JogOutward", [], call => FingersTo(call, "Hand_JogOutward", call.Machine.Task.Hand.PhysicalLimit, 0, wait: false)),
        Instruction("Hand_Stop", [], call => call.Machine.Task.Hand.Force = 0),
        Instruction("Hand_SetMaxSpeed", [P("maxSpd", "num")], call => call.Machine.Task.Hand.MaxSpeed = InRange(call, "Hand_SetMaxSpeed", call.Num(0), RapidHand.SpeedLimit)),
        Instruction("Hand_SetHoldForce", [P("holdForce", "num")], call => call.Machine.Task.Hand.HoldForce = InRange(call, "Hand_SetHoldForce", call.Num(0), RapidHand.ForceLimit)),
        Instruction("Hand_WaitMovingCompleted", [Opt("maxTime", "num")], _ => { }), // a \NoWait move is complete at once in the twin
        Function("Hand_GetActualPos", "num", [], call => call.Machine.Task.Hand.Position),
        Function("Hand_GetActualForce", "num", [], call => call.Machine.Task.Hand.Force),
        Function("Hand_IsCalibrated", "bool", [], call => call.Machine.Task.Hand.Calibrated),
    ];

    /// <summary>A grip: inward to \targetPos or closed, outward to \targetPos or the physical limit, holding with \holdForce or the hold force.</summary>
    private static void Grip(RapidCall call, string name, bool inward)
    {
        RapidHand hand = Calibrated(call, name);
        double force = call.Has(0) ? InRange(call, name + " \\holdForce", call.Num(0), RapidHand.ForceLimit) : hand.HoldForce;
        double target = call.Has(1) ? InRange(call, name + " \\targetPos", call.Num(1), hand.PhysicalLimit, zero: true) : inward ? 0 : hand.PhysicalLimit;
        FingersTo(call, name, target, force, wait: !call.Has(2));
    }

    private static RapidHand Calibrated(RapidCall call, string name) => call.Machine.Task.Hand is { Calibrated: true } hand
        ? hand
        : throw call.Error(RapidErrorNumbers.ByName["ERR_HAND_NOTCALIBRATED"], $"{name}: the gripper is not calibrated (Hand_Initialize \\Calibrate first)");

    /// <summary><paramref name="value"/> when it is within (0, <paramref name="limit"/>] ([0, limit] with <paramref name="zero"/>); else ERR_ARGVALERR.</summary>
    private static double InRange(RapidCall call, string name, double value, double limit, bool zero = false) =>
        (zero ? value >= 0 : value > 0) && value <= limit
            ? value
            : throw ArgumentError(call, $"{name}: {RapidValues.FormatNumber(value)} is not within {(zero ? "0" : "0 (excluded)")} to {RapidValues.FormatNumber(limit)}");

    /// <summary>Moves the fingers to <paramref name="target"/> mm at the maximum speed (waiting for them when <paramref name="wait"/>), holding with <paramref name="force"/>.</summary>
    private static void FingersTo(RapidCall call, string name, double target, double force, bool wait)
    {
        RapidTask task = call.Machine.Task;
        RapidHand hand = task.Hand;
        double seconds = Math.Abs(target - hand.Position) / hand.MaxSpeed;
        if (wait && seconds > 0)
        {
            RapidTwinController c = task.Controller;
            WaitServingTraps(task, seconds, task.IsMotionTask ? s => c.Clock.Wait(s, task.CancellationToken) : s => c.Clock.WaitWall(s, task.CancellationToken));
        }
        (hand.Position, hand.Force) = (target, force);
        task.Controller.Arm.Record(call.Line, TwinTraceKind.Message, string.Create(CultureInfo.InvariantCulture, $"{name}: fingers at {target} mm"));
    }
}
