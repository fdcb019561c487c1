using System.Globalization;
using System.Text.RegularExpressions;

namespace Machina;

/// <summary>Universal Robots arms: URScript programs, Machina's URScript driver online, a virtual UR5e (see <see cref="BrandRegistry"/>).</summary>
internal static partial class UrBrand
{
    /// <summary>The Universal Robots brand.</summary>
    internal static BrandDefinition Definition { get; } = new(RobotType.UR, "ur", BrandKind.Arm, () => new UrScriptCompiler())
    {
        Aliases = ["universal robots", "universalrobots"],
        Online = new UrOnline(),
        ModelBrand = "UR",
        Family = KinematicFamily.UniversalRobots,
        DefaultModel = "UR5e",
        Models = UniversalRobotsCatalog.Build,
        Timing = new UrMotionTiming(),
        DefaultPort = UrPorts.StandardScript,
        DriverNextSteps = NextSteps,
        DriverConnectsBack = true,
        InstructionName = Instruction,
    };

    /// <summary>What to do with the driver file (docs/getting-started.md): nothing to load, <c>machina run</c> sends it.</summary>
    private static string NextSteps(int fileCount, string host, int port) =>
        $"Wrote {fileCount} UR driver file{(fileCount == 1 ? "" : "s")} for reading, filled in with {host}:{port} as the computer it connects back to. " +
        "Nothing to load on a UR: machina run sends this script to the robot's script port itself, with this computer's address " +
        "and a free port filled in. Give the robot a fixed address the computer can reach (and that can reach the computer), put " +
        $"an e-Series robot in remote control, then: machina run PROGRAM --brand ur --host ROBOT_ADDRESS --port {UrPorts.StandardScript}";

    /// <summary>The instruction of a driver request such as <c>2 1 3000 1000 4000 …</c> (its second number, docs/protocol-ur.md).</summary>
    private static string? Instruction(string request) =>
        Code().Match(request) is { Success: true } m && int.TryParse(m.Groups["code"].Value, NumberStyles.Integer, CultureInfo.InvariantCulture, out int code)
            && Enum.IsDefined((UrInstructionCode)code) ? ((UrInstructionCode)code).ToString() : null;

    [GeneratedRegex(@"^-?\d+\s+(?<code>\d+)")]
    private static partial Regex Code();
}
