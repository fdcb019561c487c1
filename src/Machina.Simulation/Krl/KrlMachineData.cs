using System.Text.RegularExpressions;

namespace Machina.Simulation.Krl;

/// <summary>
/// The controller's machine data lists: <c>$MACHINE.DAT</c> and <c>$ROBCOR.DAT</c> (KRC:\R1\Mada), <c>$CUSTOM.DAT</c> and
/// <c>$OPTION.DAT</c> (KRC:\STEU\Mada). They configure the controller itself (serial interfaces for CREAD/CWRITE with their
/// <c>CHANNEL</c> lines and <c>SER</c> data, the submit programs started at a cold boot in <c>PRO_IO_T</c> data, the spline
/// defaults such as <c>$TOOL_DIRECTION</c> of type <c>AXIS_OF_COORDINATES</c>, workspaces, the arm's machine data) and are no
/// program module: every controller has its own. Repositories ship them beside their programs (ros-industrial's motion_eki has
/// a <c>$custom.dat</c>); the twin keeps its own system variables and sets such a file aside when a folder is loaded, saying so.
/// </summary>
internal static partial class KrlMachineData
{
    private static readonly string[] Names = ["$MACHINE", "$ROBCOR", "$CUSTOM", "$OPTION"];

    /// <summary>The machine data list <paramref name="text"/> (a .dat named <paramref name="file"/>) declares, or null when it is a program's data list.</summary>
    public static string? ListOf(string file, string text)
    {
        if (!file.EndsWith(".dat", StringComparison.OrdinalIgnoreCase) || !Path.GetFileName(file).StartsWith('$'))
        {
            return null;
        }
        Match defdat = DefdatLine().Match(text);
        return defdat.Success && Names.Contains(defdat.Groups[1].Value, StringComparer.OrdinalIgnoreCase) ? defdat.Groups[1].Value.ToUpperInvariant() : null;
    }

    [GeneratedRegex(@"^\s*DEFDAT\s+(\$[A-Za-z_][A-Za-z0-9_]*)", RegexOptions.IgnoreCase | RegexOptions.Multiline | RegexOptions.CultureInvariant)]
    private static partial Regex DefdatLine();
}
