namespace Machina.Simulation.Krl;

/// <summary>
/// The system variables published programs read besides the twin's own: the measured pose ($AXIS_ACT_MEAS, $POS_ACT_MES: on the
/// twin the commanded one, as it has no servo lag), the timer flags ($TIMER_FLAG), the cyclic flags ($CYCFLAG: stored as
/// assigned; the controller's cyclic evaluation of their expression is not modelled) and the operating mode ($MODE_OP: #T1, as
/// KUKA.OfficeLite starts).
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
        Add(new KrlCell("$POS_ACT_MES", KrlTypes.E6Pos, null!) { ReadOnly = true, Read = controller.PositionNow });
        KrlType flags = KrlType.Array(KrlType.Bool, KrlTwinController.TimerCount);
        Add(new KrlCell("$TIMER_FLAG", flags, KrlValues.Default(flags)) { ReadOnly = true, Read = controller.TimerFlags });
        KrlType cyclic = KrlType.Array(KrlType.Bool, CyclicFlagCount);
        Add(new KrlCell("$CYCFLAG", cyclic, KrlValues.Default(cyclic)));
        Add(new KrlCell("$MODE_OP", KrlType.Enum, new KrlEnumValue("T1")) { ReadOnly = true });
    }
}
