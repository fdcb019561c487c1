namespace Machina.Simulation.Krl;

/// <summary>
/// The predefined KRL types the twin knows: the simple types, the geometric structures of the KUKA system software (AXIS,
/// E6AXIS, FRAME, POS, E6POS), the motion settings ($VEL, $ACC, $APO), EthernetKRL's EKI_STATUS and the KrlMsg structures.
/// </summary>
internal static class KrlTypes
{
    private static readonly (string, KrlType)[] Xyzabc =
        [("X", KrlType.Real), ("Y", KrlType.Real), ("Z", KrlType.Real), ("A", KrlType.Real), ("B", KrlType.Real), ("C", KrlType.Real)];

    private static readonly (string, KrlType)[] Axes =
        [("A1", KrlType.Real), ("A2", KrlType.Real), ("A3", KrlType.Real), ("A4", KrlType.Real), ("A5", KrlType.Real), ("A6", KrlType.Real)];

    private static readonly (string, KrlType)[] External =
        [("E1", KrlType.Real), ("E2", KrlType.Real), ("E3", KrlType.Real), ("E4", KrlType.Real), ("E5", KrlType.Real), ("E6", KrlType.Real)];

    /// <summary>FRAME: X, Y, Z (mm), A, B, C (degrees).</summary>
    public static KrlType Frame { get; } = KrlType.Struct("FRAME", Xyzabc);

    /// <summary>POS: a FRAME with the status S and turn T.</summary>
    public static KrlType Pos { get; } = KrlType.Struct("POS", [.. Xyzabc, ("S", KrlType.Int), ("T", KrlType.Int)]);

    /// <summary>E6POS: a POS with the external axes E1 to E6.</summary>
    public static KrlType E6Pos { get; } = KrlType.Struct("E6POS", [.. Xyzabc, ("S", KrlType.Int), ("T", KrlType.Int), .. External]);

    /// <summary>AXIS: A1 to A6 (degrees).</summary>
    public static KrlType Axis { get; } = KrlType.Struct("AXIS", Axes);

    /// <summary>E6AXIS: AXIS with E1 to E6.</summary>
    public static KrlType E6Axis { get; } = KrlType.Struct("E6AXIS", [.. Axes, .. External]);

    /// <summary>$VEL and $ACC: CP (m/s or m/s²), ORI1 and ORI2 (deg/s or deg/s²).</summary>
    public static KrlType Rates { get; } = KrlType.Struct("VEL_STRUC", ("CP", KrlType.Real), ("ORI1", KrlType.Real), ("ORI2", KrlType.Real));

    /// <summary>$APO: CVEL (%), CPTP (%), CDIS (mm), CORI (degrees).</summary>
    public static KrlType Apo { get; } = KrlType.Struct("APO_STRUC", ("CVEL", KrlType.Int), ("CPTP", KrlType.Int), ("CDIS", KrlType.Real), ("CORI", KrlType.Real));

    /// <summary>EthernetKRL's return value: buffered elements, read ones, error number, connection and counter.</summary>
    public static KrlType EkiStatus { get; } = KrlType.Struct("EKI_STATUS",
        ("Buff", KrlType.Int), ("Read", KrlType.Int), ("Msg_No", KrlType.Int), ("Connected", KrlType.Bool), ("Counter", KrlType.Int));

    /// <summary>A message's sender, number and text.</summary>
    public static KrlType KrlMsg { get; } = KrlType.Struct("KRLMSG_T",
        ("Modul", KrlType.Array(KrlType.Char, 24)), ("Nr", KrlType.Int), ("Msg_txt", KrlType.Array(KrlType.Char, 80)));

    /// <summary>A message parameter.</summary>
    public static KrlType KrlMsgPar { get; } = KrlType.Struct("KRLMSGPAR_T",
        ("Par_Type", KrlType.Enum), ("Par_txt", KrlType.Array(KrlType.Char, 26)), ("Par_Int", KrlType.Int), ("Par_Real", KrlType.Real), ("Par_Bool", KrlType.Bool));

    /// <summary>A message's options.</summary>
    public static KrlType KrlMsgOpt { get; } = KrlType.Struct("KRLMSGOPT_T",
        ("VL_Stop", KrlType.Bool), ("Clear_P_Reset", KrlType.Bool), ("Clear_P_SAW", KrlType.Bool), ("Log_to_DB", KrlType.Bool));

    /// <summary>RSIERR, what RSI 2's ST_ routines return (#RSIOK when they succeeded).</summary>
    public static KrlType RsiError => KrlType.Enum;

    private static readonly Dictionary<string, KrlType> ByName = new(StringComparer.OrdinalIgnoreCase)
    {
        ["INT"] = KrlType.Int, ["REAL"] = KrlType.Real, ["BOOL"] = KrlType.Bool, ["CHAR"] = KrlType.Char,
        ["FRAME"] = Frame, ["POS"] = Pos, ["E6POS"] = E6Pos, ["AXIS"] = Axis, ["E6AXIS"] = E6Axis,
        ["EKI_STATUS"] = EkiStatus, ["KrlMsg_T"] = KrlMsg, ["KrlMsgPar_T"] = KrlMsgPar, ["KrlMsgOpt_T"] = KrlMsgOpt,
        ["PDAT"] = KrlTemplateTypes.Pdat, ["LDAT"] = KrlTemplateTypes.Ldat, ["FDAT"] = KrlTemplateTypes.Fdat,
        ["BASIS_SUGG_T"] = KrlTemplateTypes.BasisSuggestions,
        ["PRO_STATE"] = KrlType.Enum, ["RSIERR"] = KrlType.Enum, ["MODUS_T"] = KrlType.Enum, ["STATE_T"] = KrlProgramManagement.StateType,
    };

    /// <summary>The predefined type called <paramref name="name"/>, or null.</summary>
    public static KrlType? Find(string name) => ByName.GetValueOrDefault(name);

    /// <summary>True for the Cartesian structures (FRAME, POS, E6POS), which assign to one another component by component.</summary>
    public static bool IsCartesian(KrlType type) => type == Frame || type == Pos || type == E6Pos;

    /// <summary>The bits of the status S and turn T components of a POS or E6POS (0 for other types): see <see cref="KrlStructValue.Unset"/>.</summary>
    public static int StatusTurnBits(KrlType type) => type == Pos || type == E6Pos ? (1 << 6) | (1 << 7) : 0;

    /// <summary>True for the axis structures (AXIS, E6AXIS).</summary>
    public static bool IsAxes(KrlType type) => type == Axis || type == E6Axis;

    /// <summary>True when a value of <paramref name="from"/> may be assigned to <paramref name="to"/>.</summary>
    public static bool Assignable(KrlType to, KrlType from)
    {
        if (to == from)
        {
            return true;
        }
        return to.Kind switch
        {
            KrlKind.Int or KrlKind.Real => from.IsNumber,
            KrlKind.Enum => from.Kind == KrlKind.Enum,
            KrlKind.Char => from.Kind == KrlKind.Int, // an ASCII code (EOL[1] = 13)
            KrlKind.Struct => (IsCartesian(to) && IsCartesian(from)) || (IsAxes(to) && IsAxes(from)),
            KrlKind.Array => from.Kind == KrlKind.Array && from.Element!.Kind == to.Element!.Kind && from.Sizes.Count == to.Sizes.Count,
            _ => false,
        };
    }
}
