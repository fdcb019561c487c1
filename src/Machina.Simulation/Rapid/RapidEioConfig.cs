using System.Globalization;
using System.Text.RegularExpressions;

namespace Machina.Simulation.Rapid;

/// <summary>
/// The signals of a controller's IO configuration file (EIO.cfg, as a backup's SYSPAR folder holds it): each instance of the
/// <c>EIO_SIGNAL</c> type with its <c>-Name</c>, <c>-SignalType</c> (DI, DO, AI, AO, GI, GO) and <c>-Default</c> value. The
/// rest (buses, units, cross connections, system signals) is not read.
/// </summary>
internal static partial class RapidEioConfig
{
    /// <summary>The signals of EIO.cfg text <paramref name="text"/>: name, RAPID type (signaldi…) and value at start-up.</summary>
    public static IReadOnlyList<(string Name, string Type, double Default)> Signals(string text)
    {
        var signals = new List<(string, string, double)>();
        bool inSignals = false;
        // Instances are separated by blank lines; a line ending in '\' goes on on the next one.
        foreach (string instance in Regex.Split(text.Replace("\\\r\n", " ", StringComparison.Ordinal).Replace("\\\n", " ", StringComparison.Ordinal), @"\r?\n"))
        {
            string line = instance.Trim();
            if (TypeHeader().Match(line) is { Success: true } header)
            {
                inSignals = header.Groups[1].Value == "EIO_SIGNAL";
                continue;
            }
            if (!inSignals || line.Length == 0 || line[0] == '#')
            {
                continue;
            }
            string? name = Attribute(line, "Name"), type = Attribute(line, "SignalType");
            if (name is null || type is null)
            {
                continue;
            }
            double value = double.TryParse(Attribute(line, "Default"), NumberStyles.Float, CultureInfo.InvariantCulture, out double d) ? d : 0;
            signals.Add((name, "signal" + type.ToLowerInvariant(), value));
        }
        return signals;
    }

    private static string? Attribute(string line, string attribute) =>
        Regex.Match(line, $"-{attribute}\\s+(\"([^\"]*)\"|(\\S+))", RegexOptions.CultureInvariant) is { Success: true } m
            ? (m.Groups[2].Success ? m.Groups[2].Value : m.Groups[3].Value)
            : null;

    [GeneratedRegex(@"^([A-Z_]+):$", RegexOptions.CultureInvariant)]
    private static partial Regex TypeHeader();
}
