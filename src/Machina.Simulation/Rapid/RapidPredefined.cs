namespace Machina.Simulation.Rapid;

/// <summary>
/// The predefined data of a task (RAPID reference manual, "Predefined data"): speeds v5…v7000 and vmax, zones z0…z200 and fine,
/// tool0, wobj0, load0, the error numbers ERR_…, the interrupt and socket constants, pi, and the IO configuration's signals.
/// </summary>
internal static partial class RapidPredefined
{
    private static readonly int[] Speeds = [5, 10, 20, 30, 40, 50, 60, 80, 100, 150, 200, 300, 400, 500, 600, 800, 1000, 1500, 2000, 2500, 3000, 4000, 5000, 6000, 7000];

    // zonedata: name, pzone_tcp, pzone_ori, pzone_eax, zone_ori, zone_leax, zone_reax.
    private static readonly (string Name, double Tcp, double Ori, double Eax, double ZOri, double Leax, double Reax)[] Zones =
    [
        ("z0", 0.3, 0.3, 0.3, 0.03, 0.3, 0.03), ("z1", 1, 1, 1, 0.1, 1, 0.1), ("z5", 5, 8, 8, 0.8, 8, 0.8), ("z10", 10, 15, 15, 1.5, 15, 1.5),
        ("z15", 15, 23, 23, 2.3, 23, 2.3), ("z20", 20, 30, 30, 3, 30, 3), ("z30", 30, 45, 45, 4.5, 45, 4.5), ("z40", 40, 60, 60, 6, 60, 6),
        ("z50", 50, 75, 75, 7.5, 75, 7.5), ("z60", 60, 90, 90, 9, 90, 9), ("z80", 80, 120, 120, 12, 120, 12), ("z100", 100, 150, 150, 15, 150, 15),
        ("z150", 150, 225, 225, 23, 225, 23), ("z200", 200, 300, 300, 30, 300, 30),
    ];

    private static readonly (string Name, double Value)[] Constants =
    [
        ("pi", Math.PI), ("COMMON_ERR", 0), ("OP_STATE", 1), ("SYSTEM_ERR", 2), ("HARDWARE_ERR", 3), ("PROGRAM_ERR", 4), ("MOTION_ERR", 5),
        ("IO_COM_ERR", 7), ("USER_DEF_ERR", 8), ("TYPE_ERR", 3), ("TYPE_WARN", 2), ("TYPE_STATE", 1), ("TYPE_ALL", 0),
        ("SOCKET_CREATED", 1), ("SOCKET_CONNECTED", 2), ("SOCKET_BOUND", 3), ("SOCKET_LISTENING", 4), ("SOCKET_CLOSED", 5),
        ("high", 1), ("low", 0), ("edge", 2),
    ];

    /// <summary>Adds the predefined data to <paramref name="program"/>.</summary>
    public static void AddTo(RapidProgram program, RapidTwinController controller)
    {
        foreach (int v in Speeds)
        {
            Add(program, $"v{v}", RapidTypes.Speeddata, Record(RapidTypes.Speeddata, v, 500, 5000, 1000));
        }
        Add(program, "vmax", RapidTypes.Speeddata, Record(RapidTypes.Speeddata, 5000, 500, 5000, 1000));
        foreach ((string name, double tcp, double ori, double eax, double zori, double leax, double reax) in Zones)
        {
            Add(program, name, RapidTypes.Zonedata, new RapidRecord(RapidTypes.Zonedata, [false, tcp, ori, eax, zori, leax, reax]));
        }
        Add(program, "fine", RapidTypes.Zonedata, new RapidRecord(RapidTypes.Zonedata, [true, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0]));
        Add(program, "load0", RapidTypes.Loaddata, Load0());
        Add(program, "ROB_1", RapidTypes.All["mecunit"], new object()); // the arm's mechanical unit (GetMotorTorque \MecUnit, GetJointData \MechUnit)
        Add(program, "tool0", RapidTypes.Tooldata, new RapidRecord(RapidTypes.Tooldata, [true, RapidGeometry.ToPoseRecord(Pose.Identity), Load0()]));
        Add(program, "wobj0", RapidTypes.Wobjdata, new RapidRecord(RapidTypes.Wobjdata,
            [false, true, "", RapidGeometry.ToPoseRecord(Pose.Identity), RapidGeometry.ToPoseRecord(Pose.Identity)]));
        foreach ((string name, int number) in RapidErrorNumbers.ByName)
        {
            Add(program, name, RapidTypes.All["errnum"], (double)number);
        }
        foreach ((string name, double value) in Constants)
        {
            Add(program, name, RapidTypes.Num, value);
        }
        AddLanguageConstants(program);
        // The data of the system module USER (user.sys) that a controller loads into every task: registers reg1…reg5 and clock1. A
        // program's own user.sys (or data of those names) takes their place.
        for (int r = 1; r <= 5; r++)
        {
            AddVariable(program, $"reg{r}", RapidTypes.Num);
        }
        AddVariable(program, "clock1", RapidTypes.All["clock"]);
        foreach ((string name, string type) in controller.Options.Signals)
        {
            Add(program, name, RapidTypes.All[type], new RapidSignalRef { Signal = name });
        }
    }

    private static void AddVariable(RapidProgram program, string name, RapidType type)
    {
        var dataType = new RapidDataType(type);
        program.Globals[name] = new RapidCell(name, dataType, RapidStorage.Var, RapidValues.Default(dataType));
        program.Predefined.Add(name);
    }

    private static RapidRecord Load0() => new(RapidTypes.Loaddata, [0.001, RapidGeometry.ToPosRecord(new Vector(0, 0, 0.001)), RapidGeometry.ToOrientRecord(Rotation.Identity), 0.0, 0.0, 0.0]);

    private static RapidRecord Record(RapidType type, params double[] values) => new(type, [.. values.Select(v => (object)v)]);

    private static void Add(RapidProgram program, string name, RapidType type, object value)
    {
        program.Globals[name] = new RapidCell(name, new RapidDataType(type), RapidStorage.Const, value);
        program.Predefined.Add(name);
    }
}
