namespace Machina.Simulation.Rapid;

/// <summary>
/// The predefined RAPID data types (RAPID reference manual, "Data types"): the atomic types, their aliases, the motion records
/// (pos, orient, pose, confdata, robtarget, jointtarget, speeddata, zonedata, tooldata, loaddata, wobjdata…) and the non-value
/// types the instructions use (socketdev, signals, clock, intnum…).
/// </summary>
internal static partial class RapidTypes
{
    /// <summary><c>num</c></summary>
    public static readonly RapidType Num = new("num", RapidTypeKind.Num);

    /// <summary><c>dnum</c></summary>
    public static readonly RapidType Dnum = new("dnum", RapidTypeKind.Dnum, "num");

    /// <summary><c>bool</c></summary>
    public static readonly RapidType Bool = new("bool", RapidTypeKind.Bool);

    /// <summary><c>string</c></summary>
    public static readonly RapidType String = new("string", RapidTypeKind.String);

    /// <summary><c>pos</c>: x, y, z in mm.</summary>
    public static readonly RapidType Pos = Record("pos", ("x", Num), ("y", Num), ("z", Num));

    /// <summary><c>orient</c>: a quaternion q1 (scalar), q2, q3, q4.</summary>
    public static readonly RapidType Orient = Record("orient", ("q1", Num), ("q2", Num), ("q3", Num), ("q4", Num));

    /// <summary><c>pose</c>: trans and rot.</summary>
    public static readonly RapidType PoseType = Record("pose", ("trans", Pos), ("rot", Orient));

    /// <summary><c>confdata</c>: the axis quadrants.</summary>
    public static readonly RapidType Confdata = Record("confdata", ("cf1", Num), ("cf4", Num), ("cf6", Num), ("cfx", Num));

    /// <summary><c>extjoint</c>: six external axes (9E9: not used).</summary>
    public static readonly RapidType Extjoint = Record("extjoint", ("eax_a", Num), ("eax_b", Num), ("eax_c", Num), ("eax_d", Num), ("eax_e", Num), ("eax_f", Num));

    /// <summary><c>robjoint</c>: the six robot axes in degrees.</summary>
    public static readonly RapidType Robjoint = Record("robjoint", ("rax_1", Num), ("rax_2", Num), ("rax_3", Num), ("rax_4", Num), ("rax_5", Num), ("rax_6", Num));

    /// <summary><c>robtarget</c></summary>
    public static readonly RapidType Robtarget = Record("robtarget", ("trans", Pos), ("rot", Orient), ("robconf", Confdata), ("extax", Extjoint));

    /// <summary><c>jointtarget</c></summary>
    public static readonly RapidType Jointtarget = Record("jointtarget", ("robax", Robjoint), ("extax", Extjoint));

    /// <summary><c>speeddata</c>: v_tcp (mm/s), v_ori (deg/s), v_leax (mm/s), v_reax (deg/s).</summary>
    public static readonly RapidType Speeddata = Record("speeddata", ("v_tcp", Num), ("v_ori", Num), ("v_leax", Num), ("v_reax", Num));

    /// <summary><c>zonedata</c></summary>
    public static readonly RapidType Zonedata = Record("zonedata", ("finep", Bool), ("pzone_tcp", Num), ("pzone_ori", Num), ("pzone_eax", Num),
        ("zone_ori", Num), ("zone_leax", Num), ("zone_reax", Num));

    /// <summary><c>loaddata</c>: mass (kg), cog, aom, inertia.</summary>
    public static readonly RapidType Loaddata = Record("loaddata", ("mass", Num), ("cog", Pos), ("aom", Orient), ("ix", Num), ("iy", Num), ("iz", Num));

    /// <summary><c>tooldata</c></summary>
    public static readonly RapidType Tooldata = Record("tooldata", ("robhold", Bool), ("tframe", PoseType), ("tload", Loaddata));

    /// <summary><c>wobjdata</c></summary>
    public static readonly RapidType Wobjdata = Record("wobjdata", ("robhold", Bool), ("ufprog", Bool), ("ufmec", String), ("uframe", PoseType), ("oframe", PoseType));

    /// <summary>Every predefined type, by name.</summary>
    public static IReadOnlyDictionary<string, RapidType> All { get; } = Build();

    /// <summary>True for a signal type (signaldo, signalai…).</summary>
    public static bool IsSignal(RapidType type) => type.Name.StartsWith("signal", StringComparison.OrdinalIgnoreCase);

    private static RapidType Record(string name, params (string Name, RapidType Type)[] fields) =>
        new(name, [.. fields.Select(f => (f.Name, new RapidDataType(f.Type)))]);

    private static Dictionary<string, RapidType> Build()
    {
        RapidType[] types =
        [
            Num, Dnum, Bool, String, Pos, Orient, PoseType, Confdata, Extjoint, Robjoint, Robtarget, Jointtarget, Speeddata, Zonedata,
            Loaddata, Tooldata, Wobjdata,
            new("errnum", RapidTypeKind.Num, "num"), new("intnum", RapidTypeKind.Num, "num"), new("errdomain", RapidTypeKind.Num, "num"),
            new("errtype", RapidTypeKind.Num, "num"), new("socketstatus", RapidTypeKind.Num, "num"), new("errstr", RapidTypeKind.String, "string"),
            new("dionum", RapidTypeKind.Num, "num"),
            new("socketdev", RapidTypeKind.Opaque, create: () => new RapidSocketDevice()),
            new("clock", RapidTypeKind.Opaque, create: () => new RapidClock()),
            new("trapdata", RapidTypeKind.Opaque, create: () => new RapidTrapData()),
            new("signaldi", RapidTypeKind.Opaque, create: () => new RapidSignalRef()), new("signaldo", RapidTypeKind.Opaque, create: () => new RapidSignalRef()),
            new("signalai", RapidTypeKind.Opaque, create: () => new RapidSignalRef()), new("signalao", RapidTypeKind.Opaque, create: () => new RapidSignalRef()),
            new("signalgi", RapidTypeKind.Opaque, create: () => new RapidSignalRef()), new("signalgo", RapidTypeKind.Opaque, create: () => new RapidSignalRef()),
            .. LanguageTypes(),
        ];
        return types.ToDictionary(t => t.Name, StringComparer.OrdinalIgnoreCase);
    }
}

/// <summary>A <c>clock</c>: a stopwatch of program time (ClkStart, ClkStop, ClkRead, ClkReset).</summary>
internal sealed class RapidClock
{
    /// <summary>Program seconds when it was started, or null when stopped.</summary>
    public double? StartedAt { get; set; }

    /// <summary>Seconds counted before the last start.</summary>
    public double Accumulated { get; set; }
}

/// <summary>A <c>trapdata</c>: what caused the interrupt a trap runs for (GetTrapData, ReadErrData).</summary>
internal sealed class RapidTrapData
{
    /// <summary>The error domain (e.g. 5 for motion).</summary>
    public double Domain { get; set; }

    /// <summary>The error number within its domain (e.g. 50 for 50050).</summary>
    public double Number { get; set; }

    /// <summary>The error type (TYPE_ERR…).</summary>
    public double Kind { get; set; }
}

/// <summary>A signal variable: the name of the controller signal it refers to (declared in the IO configuration or by AliasIO).</summary>
internal sealed class RapidSignalRef
{
    /// <summary>The signal's name, or null before AliasIO.</summary>
    public string? Signal { get; set; }
}
