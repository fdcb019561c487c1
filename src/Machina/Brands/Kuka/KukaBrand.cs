using System.Globalization;
using System.Text.RegularExpressions;

namespace Machina;

/// <summary>KUKA arms: KRL programs, Machina's KRL driver (EthernetKRL) online, a virtual KR 6 R900 sixx (see <see cref="BrandRegistry"/>).</summary>
internal static partial class KukaBrand
{
    /// <summary>The KUKA brand.</summary>
    internal static BrandDefinition Definition { get; } = new(RobotType.KUKA, "kuka", BrandKind.Arm, () => new KrlCompiler())
    {
        Online = new KukaOnline(),
        ModelBrand = "KUKA",
        Family = KinematicFamily.Opw,
        MirroredOpwJoints = true,
        DefaultModel = "KR 6 R900 sixx",
        Models = () => CatalogTable.Load("kuka-arms.txt"),
        Timing = new KukaMotionTiming(),
        DefaultPort = 7000,
        DriverNextSteps = NextSteps,
        InstructionName = Instruction,
    };

    /// <summary>What to do with the driver files (docs/getting-started.md, "Load the driver on the controller").</summary>
    private static string NextSteps(int fileCount, string host, int port) =>
        $"Wrote {fileCount} KUKA driver files for {host}:{port} (needs the KUKA.EthernetKRL option). Copy the .xml files to " +
        @"C:\KRC\ROBOTER\Config\User\Common\EthernetKRL and the .src and .dat files to R1\Program; for live positions add " +
        $"machina_kuka_monitor( ) to the USER PLC fold of sps.sub (it uses port {port + 1}; flags 1 to 3 and timer 16 must be free). " +
        $"Select machina_kuka_driver and start it in T1: it listens on {host}:{port}. Then: machina run PROGRAM --brand kuka --host {host} --port {port}";

    /// <summary>The instruction of a driver request such as <c>&lt;A ID="2" T="1" …/&gt;</c> (its T attribute, docs/protocol-kuka.md).</summary>
    private static string? Instruction(string request) =>
        Code().Match(request) is { Success: true } m && int.TryParse(m.Groups["code"].Value, NumberStyles.Integer, CultureInfo.InvariantCulture, out int code)
            && Enum.IsDefined((KukaActionCode)code) ? ((KukaActionCode)code).ToString() : null;

    [GeneratedRegex(@"\bT=""(?<code>\d+)""")]
    private static partial Regex Code();
}
