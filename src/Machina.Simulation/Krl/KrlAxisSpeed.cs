using Machina.Simulation.Twin;

namespace Machina.Simulation.Krl;

/// <summary>
/// $VEL_AXIS_ACT: each axis's speed now, in % of its maximum speed, signed as the axis turns. The machine data that scale it:
/// $VEL_AXIS_MA, the maximum motor speed in rpm, and $RAT_MOT_AX, the gear ratio motor : axis ({N, D}); the twin has no motors,
/// so its ratio is 1 : 1 and $VEL_AXIS_MA is the axis's own maximum in rpm (the model's axis speed, or the twin's default, / 6),
/// and <c>$VEL_AXIS_MA[i] * $RAT_MOT_AX[i].D / $RAT_MOT_AX[i].N * 6</c> is the axis's maximum in °/s as on a controller. The twin
/// has no servo model: the speed is the mean over the time since the program last read it (the arm moves at constant speed along a
/// motion in real time, so a program that reads it during a motion, e.g. from a timer interrupt, reads that speed; its first read
/// gives 0); reads at the same moment give the same values.
/// </summary>
internal sealed class KrlAxisSpeed(KrlTwinController controller)
{
    private readonly Lock _gate = new();
    private readonly double[] _percent = new double[12];
    private Joints? _joints;
    private double _at;

    /// <summary>The gear ratio's type (RATIO: N motor turns for D axis turns).</summary>
    public static KrlType Ratio { get; } = KrlType.Struct("RATIO", ("N", KrlType.Int), ("D", KrlType.Int));

    /// <summary>$VEL_AXIS_MA: the maximum (motor) speed of each axis in rpm (A1 to A6; the 6 external axes 0).</summary>
    public KrlArrayValue Maxima()
    {
        KrlType type = KrlType.Array(KrlType.Real, 12);
        return new KrlArrayValue(type, [.. Enumerable.Range(0, 12).Select(i => (object)(i < 6 ? MaxSpeed(i) / 6 : 0.0))]);
    }

    /// <summary>$RAT_MOT_AX: 1 : 1 for every axis (the twin has no gears).</summary>
    public static KrlArrayValue Ratios()
    {
        KrlType type = KrlType.Array(Ratio, 12);
        return new KrlArrayValue(type, [.. Enumerable.Range(0, 12).Select(_ => (object)new KrlStructValue(Ratio, [KrlValues.Box(1), KrlValues.Box(1)]))]);
    }

    /// <summary>$VEL_AXIS_ACT now (12 REAL, the external axes 0).</summary>
    public KrlArrayValue Read()
    {
        TwinClock clock = controller.Clock;
        double now = clock.RealTime ? controller.Options.Time.GetElapsedTime(0, controller.Options.Time.GetTimestamp()).TotalSeconds : clock.Seconds;
        Joints joints = controller.Arm.Joints;
        lock (_gate)
        {
            if (_joints is not { } last)
            {
                Array.Clear(_percent);
            }
            else if (now > _at)
            {
                for (int i = 0; i < 6; i++)
                {
                    _percent[i] = (joints[i] - last[i]) / (now - _at) / MaxSpeed(i) * 100;
                }
            }
            if (_joints is null || now > _at)
            {
                _joints = joints;
                _at = now;
            }
            KrlType type = KrlType.Array(KrlType.Real, 12);
            return new KrlArrayValue(type, [.. _percent.Select(p => (object)p)]);
        }
    }

    private double MaxSpeed(int axis) => controller.Options.Model.MaxJointSpeeds is { } speeds ? speeds[axis] : controller.Options.DefaultAxisSpeed;
}
