namespace Machina.Simulation.Krl;

/// <summary>
/// The controller status variables published programs report to their clients (an EthernetKRL server's state messages): the
/// drives ($DRIVES_ENABLE, written by the program; $PERI_RDY and $COULD_START_MOTION follow it), the safety circuit
/// ($ALARM_STOP, $ALARM_STOP_INTERN, $USER_SAF: TRUE, no emergency stop and the guard closed, as on a KUKA.OfficeLite), the
/// operating mode ($T1 TRUE, $T2, $AUT, $EXT FALSE, as $MODE_OP), the robot program ($PRO_ACT while it runs, $PRO_MOVE while it
/// runs a motion statement, $PRO_NAME1 the main routine's name) and the robot ($NUM_AX 6, $EX_AX_NUM 0, $ROBTRAFO the arm's
/// name, $V_R1MADA the twin's machine data version).
/// </summary>
internal static partial class KrlSystemVariables
{
    private static readonly KrlType Name32 = KrlType.Array(KrlType.Char, 32);

    /// <summary>Adds the variables above to <paramref name="environment"/>.</summary>
    public static void AddStatus(KrlEnvironment environment, KrlTwinController controller)
    {
        void Add(KrlCell cell) => environment.System[cell.Name] = cell;
        Add(new KrlCell("$DRIVES_ENABLE", KrlType.Bool, true));
        bool Drives() => (bool)environment.System["$DRIVES_ENABLE"].Value;
        Add(new KrlCell("$PERI_RDY", KrlType.Bool, true) { ReadOnly = true, Read = () => KrlValues.Box(Drives()) });
        Add(new KrlCell("$COULD_START_MOTION", KrlType.Bool, true) { ReadOnly = true, Read = () => KrlValues.Box(Drives()) });
        foreach (string name in (string[])["$ALARM_STOP", "$ALARM_STOP_INTERN", "$USER_SAF", "$T1"])
        {
            Add(new KrlCell(name, KrlType.Bool, true) { ReadOnly = true });
        }
        foreach (string name in (string[])["$T2", "$AUT", "$EXT"])
        {
            Add(new KrlCell(name, KrlType.Bool, false) { ReadOnly = true });
        }
        Add(new KrlCell("$PRO_ACT", KrlType.Bool, false) { ReadOnly = true, Read = () => KrlValues.Box(controller.State == KrlProgramState.Running) });
        Add(new KrlCell("$PRO_MOVE", KrlType.Bool, false) { ReadOnly = true, Read = () => KrlValues.Box(controller.RunsMotion) });
        Add(new KrlCell("$PRO_NAME1", Name32, null!) { ReadOnly = true, Read = () => Text32((controller.MainRoutine ?? "").ToUpperInvariant()) });
        Add(new KrlCell("$NUM_AX", KrlType.Int, 6) { ReadOnly = true });
        Add(new KrlCell("$EX_AX_NUM", KrlType.Int, 0) { ReadOnly = true });
        Add(new KrlCell("$ROBTRAFO", Name32, Text32(ModelName(controller.Options.Model)[1..].Replace(" C4", "", StringComparison.Ordinal))) { ReadOnly = true });
        Add(new KrlCell("$V_R1MADA", Name32, Text32("MACHINA TWIN")) { ReadOnly = true });
    }

    /// <summary>A CHAR[32] value holding <paramref name="text"/> (the rest NUL).</summary>
    private static KrlArrayValue Text32(string text)
    {
        object[] items = new object[32];
        KrlValues.SetText(items, 0, 32, text);
        return new KrlArrayValue(Name32, items);
    }
}
