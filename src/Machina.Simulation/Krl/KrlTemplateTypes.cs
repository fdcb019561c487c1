namespace Machina.Simulation.Krl;

/// <summary>
/// The types of the KUKA program templates and inline forms (declared in the system software's $OPERATE.DAT): the motion data
/// of a PTP (PDAT) and of a CP motion (LDAT), the frame data of a point (FDAT) and the inline forms' suggestions
/// (BASIS_SUGG_T). The twin reads the components a template writes; LDAT's CB (the spline's orientation guidance) it leaves out.
/// </summary>
internal static class KrlTemplateTypes
{
    private static readonly KrlType Name24 = KrlType.Array(KrlType.Char, 24);

    /// <summary>PDAT: VEL and ACC (% of the axes' maximum), APO_DIST (mm), APO_MODE, GEAR_JERK, EXAX_IGN.</summary>
    public static KrlType Pdat { get; } = KrlType.Struct("PDAT", ("VEL", KrlType.Real), ("ACC", KrlType.Real), ("APO_DIST", KrlType.Real),
        ("APO_MODE", KrlType.Enum), ("GEAR_JERK", KrlType.Real), ("EXAX_IGN", KrlType.Int));

    /// <summary>LDAT: VEL (m/s), ACC (%), APO_DIST (mm), APO_FAC, AXIS_VEL, AXIS_ACC, ORI_TYP, CIRC_TYP, JERK_FAC, GEAR_JERK, EXAX_IGN.</summary>
    public static KrlType Ldat { get; } = KrlType.Struct("LDAT", ("VEL", KrlType.Real), ("ACC", KrlType.Real), ("APO_DIST", KrlType.Real),
        ("APO_FAC", KrlType.Real), ("AXIS_VEL", KrlType.Real), ("AXIS_ACC", KrlType.Real), ("ORI_TYP", KrlType.Enum), ("CIRC_TYP", KrlType.Enum),
        ("JERK_FAC", KrlType.Real), ("GEAR_JERK", KrlType.Real), ("EXAX_IGN", KrlType.Int));

    /// <summary>FDAT: the tool and base numbers of a point (TOOL_DATA and BASE_DATA indexes, 0: none), IPO_FRAME, POINT2, TQ_STATE.</summary>
    public static KrlType Fdat { get; } = KrlType.Struct("FDAT", ("TOOL_NO", KrlType.Int), ("BASE_NO", KrlType.Int), ("IPO_FRAME", KrlType.Enum),
        ("POINT2", Name24), ("TQ_STATE", KrlType.Bool));

    /// <summary>BASIS_SUGG_T: the names the inline forms suggest next (text only).</summary>
    public static KrlType BasisSuggestions { get; } = KrlType.Struct("BASIS_SUGG_T", ("POINT1", Name24), ("POINT2", Name24), ("CP_PARAMS", Name24),
        ("PTP_PARAMS", Name24), ("CONT", Name24), ("CP_VEL", Name24), ("PTP_VEL", Name24), ("SYNC_PARAMS", Name24), ("SPL_NAME", Name24), ("A_PARAMS", Name24));

    /// <summary>A PDAT or LDAT value: VEL, ACC and APO_DIST given, APO_MODE #CDIS, the rest at 0 or 100 as $CONFIG.DAT has them.</summary>
    public static KrlStructValue Motion(KrlType type, double velocity, double acceleration, double distance)
    {
        var value = (KrlStructValue)KrlValues.Default(type);
        value.Values[0] = velocity;
        value.Values[1] = acceleration;
        value.Values[2] = distance;
        if (type == Pdat)
        {
            value.Values[3] = new KrlEnumValue("CDIS");
            value.Values[4] = 50.0;
        }
        else
        {
            value.Values[3] = 50.0;
            value.Values[4] = 100.0;
            value.Values[5] = 100.0;
            value.Values[6] = new KrlEnumValue("VAR");
            value.Values[7] = new KrlEnumValue("BASE");
            value.Values[8] = 50.0;
            value.Values[9] = 50.0;
        }
        return value;
    }
}
