namespace Machina.Simulation.Krl;

/// <summary>
/// The system variables published programs read besides the twin's own: the measured pose ($AXIS_ACT_MEAS, $POS_ACT_MES: on the
/// twin the commanded one, as it has no servo lag), the timer flags ($TIMER_FLAG), the cyclic flags ($CYCFLAG: stored as
/// assigned; the controller's cyclic evaluation of their expression is not modelled), the operating mode ($MODE_OP: #T1, as
/// KUKA.OfficeLite starts), the axis speeds ($VEL_AXIS_ACT, $VEL_AXIS_MA, $RAT_MOT_AX: see <see cref="KrlAxisSpeed"/>), the axis
/// torques ($TORQUE_AXIS_ACT: 0, the twin has no dynamics) and the path maxima ($VEL_MA, $ACC_MA).
/// </summary>
internal static partial class KrlSystemVariables
{
    /// <summary>Number of cyclic flags ($CYCFLAG).</summary>
    public const int CyclicFlagCount = 256;

    /// <summary>Adds the variables above to <paramref name="environment"/>.</summary>
    public static void AddMeasured(KrlEnvironment environment, KrlTwinController controller)
    {
        void Add(KrlCell cell) => environment.System[cell.Name] = cell;
        Add(new KrlCell("$AXIS_ACT_MEAS", KrlTypes.E6Axis, null!) { ReadOnly = true, Read = controller.AxesNow });
        Add(new KrlCell("$POS_ACT_MES", KrlTypes.E6Pos, null!) { ReadOnly = true, Read = () => Given(controller.PositionNow()) });
        KrlType flags = KrlType.Array(KrlType.Bool, KrlTwinController.TimerCount);
        Add(new KrlCell("$TIMER_FLAG", flags, KrlValues.Default(flags)) { ReadOnly = true, Read = controller.TimerFlags });
        KrlType cyclic = KrlType.Array(KrlType.Bool, CyclicFlagCount);
        Add(new KrlCell("$CYCFLAG", cyclic, KrlValues.Default(cyclic)));
        Add(new KrlCell("$MODE_OP", KrlType.Enum, new KrlEnumValue("T1")) { ReadOnly = true });
        var speed = new KrlAxisSpeed(controller);
        KrlType reals12 = KrlType.Array(KrlType.Real, 12);
        Add(new KrlCell("$VEL_AXIS_ACT", reals12, KrlValues.Default(reals12)) { ReadOnly = true, Read = speed.Read });
        Add(new KrlCell("$VEL_AXIS_MA", reals12, speed.Maxima()) { ReadOnly = true });
        Add(new KrlCell("$RAT_MOT_AX", KrlType.Array(KrlAxisSpeed.Ratio, 12), KrlAxisSpeed.Ratios()) { ReadOnly = true });
        // No dynamics model: no axis carries a torque.
        Add(new KrlCell("$TORQUE_AXIS_ACT", reals12, KrlValues.Default(reals12)) { ReadOnly = true });
        // The machine data's path maxima as a third-party note gives their defaults (no KUKA manual found): 3 m/s, 400 °/s.
        Add(new KrlCell("$VEL_MA", KrlTypes.Rates, new KrlStructValue(KrlTypes.Rates, [3.0, 400.0, 400.0])) { ReadOnly = true });
        // The machine data's path accelerations, the top of $ACC's range: on the twin what an acceleration of 100 % stands for
        // (BAS #ACC_CP, an inline form's ACC), as $ACC starts (no KUKA value found for the arm).
        KrlStructValue acc = (KrlStructValue)environment.System["$ACC"].Value;
        Add(new KrlCell("$ACC_MA", KrlTypes.Rates, new KrlStructValue(KrlTypes.Rates, [controller.Options.DefaultCpAcceleration, acc.Values[1], acc.Values[2]])) { ReadOnly = true });
    }
}
