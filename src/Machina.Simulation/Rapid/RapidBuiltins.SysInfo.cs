namespace Machina.Simulation.Rapid;

/// <summary>What the controller says about itself: <c>GetSysInfo</c>.</summary>
internal static partial class RapidBuiltins
{
    /// <summary>The software version the twin's <c>GetSysInfo(\SWVersion)</c> reports (a RobotWare 6 version).</summary>
    internal const string SoftwareVersion = "6.15.0000";

    private static IEnumerable<RapidBuiltin> SysInfo() =>
    [
        // GetSysInfo: exactly one switch says which information; \RobotType is the arm the twin runs, by its configured model's name.
        Function("GetSysInfo", "string", [Sw("SerialNo"), Sw("SWVersion"), Sw("RobotType"), Sw("CtrlId"), Sw("LanIp"), Sw("CtrlLang"), Sw("SystemName")], call =>
        {
            var given = Enumerable.Range(0, 7).Where(call.Has).ToList();
            if (given.Count != 1)
            {
                throw ArgumentError(call, "GetSysInfo needs exactly one of \\SerialNo, \\SWVersion, \\RobotType, \\CtrlId, \\LanIp, \\CtrlLang, \\SystemName");
            }
            RapidTwinController c = call.Machine.Task.Controller;
            return given[0] switch
            {
                0 => "00-00000",
                1 => SoftwareVersion,
                2 => c.Options.Model.Name,
                3 => "virtual",
                4 => c.Options.LanIp,
                5 => "en",
                _ => "Machina virtual controller",
            };
        }),
    ];
}
