using System.Globalization;
using System.Text.RegularExpressions;

namespace Machina;

/// <summary>ABB arms: RAPID programs, Machina's RAPID driver online, a virtual IRB 120 (see <see cref="BrandRegistry"/>).</summary>
internal static partial class AbbBrand
{
    /// <summary>The ABB brand.</summary>
    internal static BrandDefinition Definition { get; } = new(RobotType.ABB, "abb", BrandKind.Arm, () => new RapidCompiler())
    {
        Online = new AbbOnline(),
        ModelBrand = "ABB",
        Family = KinematicFamily.Opw,
        DefaultModel = "IRB 120",
        Models = () => CatalogTable.Load("abb-arms.txt"),
        Timing = new AbbMotionTiming(),
        DefaultPort = 7000,
        DriverNextSteps = NextSteps,
        InstallDriver = AbbDriverInstaller.InstallAsync,
        InstructionName = Instruction,
    };

    /// <summary>What to do with the driver files (docs/getting-started.md, "Load the driver on the controller").</summary>
    private static string NextSteps(int fileCount, string host, int port) =>
        $"Wrote {fileCount} ABB driver files for {host}:{port}. With RobotStudio or the FlexPendant, load machina_abb_driver.mod " +
        $"into the motion task T_ROB1 and start it in manual reduced speed: it listens on {host}:{port}. For live positions, load " +
        $"machina_abb_monitor.mod into a second task, T_MACHINA_MONITOR (Multitasking option 623-1); it uses port {port + 1}. " +
        $"Then: machina run PROGRAM --brand abb --host {host} --port {port}";

    /// <summary>The instruction of a driver request such as <c>@2 1 350 50 500 …;</c> (its second number, docs/protocol-abb.md).</summary>
    private static string? Instruction(string request) =>
        Code().Match(request) is { Success: true } m && int.TryParse(m.Groups["code"].Value, NumberStyles.Integer, CultureInfo.InvariantCulture, out int code)
            && Enum.IsDefined((AbbInstructionCode)code) ? ((AbbInstructionCode)code).ToString() : null;

    [GeneratedRegex(@"^@-?\d+\s+(?<code>\d+)")]
    private static partial Regex Code();
}
