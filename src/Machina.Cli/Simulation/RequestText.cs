using System.Globalization;
using System.Text.RegularExpressions;

namespace Machina.Cli.Simulation;

/// <summary>
/// A request as a virtual controller read it, with the name of its instruction in front: <c>MoveL  @2 1 350 50 500 …;</c> (ABB),
/// <c>MoveL  2 1 3000 1000 4000 …</c> (UR, values in the driver's integer units), <c>Linear  &lt;A ID="2" T="1" …/&gt;</c> (KUKA).
/// The names are those of Machina's protocols (docs/protocol-*.md); an unknown code is shown as it is.
/// </summary>
internal static partial class RequestText
{
    /// <summary>The request of a <paramref name="brand"/> controller with its instruction's name, or as it is when it has none.</summary>
    internal static string Describe(RobotType brand, string request)
    {
        string? name = brand switch
        {
            RobotType.ABB => Code(AbbCode().Match(request)) is int abb && Enum.IsDefined((AbbInstructionCode)abb) ? ((AbbInstructionCode)abb).ToString() : null,
            RobotType.UR => Code(UrCode().Match(request)) is int ur && Enum.IsDefined((UrInstructionCode)ur) ? ((UrInstructionCode)ur).ToString() : null,
            RobotType.KUKA => Code(KukaCode().Match(request)) is int kuka && Enum.IsDefined((KukaActionCode)kuka) ? ((KukaActionCode)kuka).ToString() : null,
            _ => null,
        };
        return name is null ? request : $"{name,-16}{request}";
    }

    private static int? Code(Match m) =>
        m.Success && int.TryParse(m.Groups["code"].Value, NumberStyles.Integer, CultureInfo.InvariantCulture, out int code) ? code : null;

    [GeneratedRegex(@"^@-?\d+\s+(?<code>\d+)")]
    private static partial Regex AbbCode();

    [GeneratedRegex(@"^-?\d+\s+(?<code>\d+)")]
    private static partial Regex UrCode();

    [GeneratedRegex(@"\bT=""(?<code>\d+)""")]
    private static partial Regex KukaCode();
}
