namespace Machina.Simulation.Krl;

/// <summary>
/// The system variables a KRL twin has: frames ($BASE, $TOOL, $NULLFRAME), motion settings ($VEL, $ACC, $VEL_AXIS, $ACC_AXIS,
/// $APO, $ADVANCE), IO ($OUT, $IN, $ANOUT, $ANIN, $FLAG), timers, software limit switches, the actual pose ($POS_ACT, $AXIS_ACT) and the arm's name ($MODEL_NAME).
/// </summary>
internal static partial class KrlSystemVariables
{
    /// <summary>Number of digital outputs and inputs ($OUT, $IN).</summary>
    public const int DigitalCount = 4096;

    /// <summary>Number of analog outputs and inputs ($ANOUT, $ANIN).</summary>
    public const int AnalogCount = 32;

    /// <summary>Number of flags ($FLAG).</summary>
    public const int FlagCount = 1024;

    /// <summary>Adds the system variables of <paramref name="controller"/> to <paramref name="environment"/>.</summary>
    public static void AddTo(KrlEnvironment environment, KrlTwinController controller)
    {
        KrlTwinOptions options = controller.Options;
        void Add(KrlCell cell) => environment.System[cell.Name] = cell;
        KrlType reals12 = KrlType.Array(KrlType.Real, 12), ints12 = KrlType.Array(KrlType.Int, 12);
        Add(new KrlCell("$NULLFRAME", KrlTypes.Frame, KrlValues.Default(KrlTypes.Frame)) { ReadOnly = true });
        Add(new KrlCell("$BASE", KrlTypes.Frame, KrlValues.Default(KrlTypes.Frame)));
        Add(new KrlCell("$TOOL", KrlTypes.Frame, KrlValues.Default(KrlTypes.Frame)) { Written = _ => controller.ToolChanged() });
        Add(new KrlCell("$VEL", KrlTypes.Rates, new KrlStructValue(KrlTypes.Rates, [options.DefaultCpVelocity, 400.0, 400.0])));
        Add(new KrlCell("$ACC", KrlTypes.Rates, new KrlStructValue(KrlTypes.Rates, [options.DefaultCpAcceleration, 1000.0, 1000.0])));
        Add(new KrlCell("$VEL_AXIS", ints12, Filled(ints12, 100)));
        Add(new KrlCell("$ACC_AXIS", ints12, Filled(ints12, 100)));
        Add(new KrlCell("$APO", KrlTypes.Apo, KrlValues.Default(KrlTypes.Apo)));
        Add(new KrlCell("$ADVANCE", KrlType.Int, 3) { Written = _ => controller.AdvanceChanged() });
        Add(new KrlCell("$OV_PRO", KrlType.Int, 100));
        // The IO arrays' values are the controller's TwinIo banks of the same names, as the other twins' signals are.
        Add(KrlCell.Of(new KrlSignalArray(controller.Io, "$OUT", KrlType.Bool, DigitalCount), readOnly: false, i => controller.OutputWritten("$OUT", i)));
        Add(KrlCell.Of(new KrlSignalArray(controller.Io, "$IN", KrlType.Bool, DigitalCount), readOnly: true));
        Add(KrlCell.Of(new KrlSignalArray(controller.Io, "$ANOUT", KrlType.Real, AnalogCount), readOnly: false, i => controller.OutputWritten("$ANOUT", i)));
        Add(KrlCell.Of(new KrlSignalArray(controller.Io, "$ANIN", KrlType.Real, AnalogCount), readOnly: true));
        Add(new KrlCell("$FLAG", KrlType.Array(KrlType.Bool, FlagCount), KrlValues.Default(KrlType.Array(KrlType.Bool, FlagCount))));
        // A timer is counted up to now when it is read, started or stopped (KrlTwinController.Timers.cs).
        KrlCell timer = null!;
        timer = new KrlCell("$TIMER", KrlType.Array(KrlType.Int, 64), KrlValues.Default(KrlType.Array(KrlType.Int, 64)))
        {
            Read = () =>
            {
                controller.CountTimers();
                return timer.Box[0];
            },
        };
        Add(timer);
        Add(new KrlCell("$TIMER_STOP", KrlType.Array(KrlType.Bool, 64), Filled(KrlType.Array(KrlType.Bool, 64), true)) { Written = _ => controller.CountTimers() });
        Add(new KrlCell("$STOPMESS", KrlType.Bool, false) { ReadOnly = true });
        double[] min = options.Model.MinJoints.ToArray(), max = options.Model.MaxJoints.ToArray();
        Add(new KrlCell("$SOFTN_END", reals12, new KrlArrayValue(reals12, [.. Enumerable.Range(0, 12).Select(i => (object)(i < 6 ? min[i] : -1e6))])) { ReadOnly = true });
        Add(new KrlCell("$SOFTP_END", reals12, new KrlArrayValue(reals12, [.. Enumerable.Range(0, 12).Select(i => (object)(i < 6 ? max[i] : 1e6))])) { ReadOnly = true });
        Add(new KrlCell("$MODEL_NAME", Name32, Text32(ModelName(options.Model))) { ReadOnly = true });
        Add(new KrlCell("$POS_ACT", KrlTypes.E6Pos, null!) { ReadOnly = true, Read = () => Given(controller.PositionNow()) });
        Add(new KrlCell("$AXIS_ACT", KrlTypes.E6Axis, null!) { ReadOnly = true, Read = controller.AxesNow });
    }

    /// <summary>
    /// The arm's name as a KR C4 keeps it in <c>$MODEL_NAME[]</c>: '#', the catalogue name in capitals without spaces, then the
    /// controller (e.g. "#KR6R900SIXX C4" for the KR 6 R900 sixx).
    /// </summary>
    internal static string ModelName(RobotModel model) => "#" + model.Name.Replace(" ", "", StringComparison.Ordinal).ToUpperInvariant() + " C4";

    /// <summary>A position the controller measured: its status and turn are given (<see cref="KrlStructValue.Unset"/>).</summary>
    private static object Given(object position)
    {
        ((KrlStructValue)position).Unset = 0;
        return position;
    }

    private static KrlArrayValue Filled(KrlType type, object value) => new(type, [.. Enumerable.Repeat(value, type.Length)]);
}
