namespace Machina.Simulation.Rapid;

/// <summary>
/// The other predefined data types that programs written for a controller declare: the symbolic number types (symnum, opnum,
/// inttypes, btnres…), raw bytes, task lists and the data of instructions the twin accepts but does not act on (syncident,
/// triggdata, and so on).
/// </summary>
internal static partial class RapidTypes
{
    /// <summary><c>rawbytes</c>: up to 1024 bytes with a current length (PackRawBytes, SocketReceive \RawData…).</summary>
    public static RapidType RawBytes => All["rawbytes"];

    private static IEnumerable<RapidType> LanguageTypes() =>
    [
        new("rawbytes", RapidTypeKind.Opaque, create: () => new RapidRawBytes()),
        new("symnum", RapidTypeKind.Num, "num"), new("byte", RapidTypeKind.Num, "num"), new("opnum", RapidTypeKind.Num, "num"), new("inttypes", RapidTypeKind.Num, "num"),
        new("btnres", RapidTypeKind.Num, "num"), new("buttondata", RapidTypeKind.Num, "num"), new("icondata", RapidTypeKind.Num, "num"),
        new("taskid", RapidTypeKind.Opaque, create: () => new object()),
        new("mecunit", RapidTypeKind.Opaque, create: () => new object()),
        new("syncident", RapidTypeKind.Opaque, create: () => new object()),
        new("triggdata", RapidTypeKind.Opaque, create: () => new RapidTriggData()),
        new("iodev", RapidTypeKind.Opaque, create: () => new RapidFileDevice()),
        new("shapedata", RapidTypeKind.Opaque, create: () => new RapidShape()),
        new("wzstationary", RapidTypeKind.Opaque, create: () => new RapidWorldZone()),
        new("wztemporary", RapidTypeKind.Opaque, create: () => new RapidWorldZone()),
        Record("tasks", ("taskname", String)),
        Record("progdisp", ("pdisp", PoseType), ("eoffs", Extjoint)),
    ];
}
