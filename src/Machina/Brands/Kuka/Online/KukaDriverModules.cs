namespace Machina;

/// <summary>
/// The KRL driver, monitor and EthernetKRL configurations Machina ships (drivers/kuka), with the robot's address filled in:
/// driver channel on <c>port</c>, monitor channel on <c>port + 1</c>, and the driver's <c>$ADVANCE</c>.
/// </summary>
internal static class KukaDriverModules
{
    /// <summary>The driver's default <c>$ADVANCE</c>, as in the programs the KRL compiler writes: motions planned 3 ahead, approximation on.</summary>
    public const int DefaultAdvance = 3;

    /// <summary>The six files by file name: driver and monitor (.src, .dat) and their EthernetKRL configurations (.xml).</summary>
    /// <param name="host">The robot's address the channels listen on (its KLI network address).</param>
    /// <param name="port">The driver channel's port; the monitor uses port + 1.</param>
    /// <param name="advance">The driver's <c>$ADVANCE</c> (0 to 5): 0 acknowledges a motion only once the robot reached its target.</param>
    public static IReadOnlyDictionary<string, string> Create(string host, int port, int advance = DefaultAdvance)
    {
        ArgumentException.ThrowIfNullOrWhiteSpace(host);
        if (host.Length > 64 || host.Any(c => c is '"' or '\'' or '<' or '>' or '&' || c > 126 || char.IsControl(c) || char.IsWhiteSpace(c)))
        {
            throw new ArgumentException($"\"{host}\" is not an address an EthernetKRL channel can listen on.", nameof(host));
        }
        if (port < 1 || port > 65533)
        {
            throw new ArgumentOutOfRangeException(nameof(port), port, "The driver port must be between 1 and 65533 (EthernetKRL ports end at 65534, and the monitor uses port + 1).");
        }
        if (advance < 0 || advance > 5)
        {
            throw new ArgumentOutOfRangeException(nameof(advance), advance, "KRL's $ADVANCE goes from 0 (acknowledge after each motion) to 5.");
        }
        string Fill(string text, int p) =>
            DriverFiles.Fill(text, ("HOSTNAME", host), ("PORT", p.ToString(Num.Inv)), ("ADVANCE", advance.ToString(Num.Inv)));
        return new Dictionary<string, string>
        {
            ["machina_kuka_driver.src"] = Fill(Read("machina_kuka_driver.src"), port),
            ["machina_kuka_driver.dat"] = Read("machina_kuka_driver.dat"),
            ["machina_kuka_server.xml"] = Fill(Read("machina_kuka_server.xml"), port),
            ["machina_kuka_monitor.src"] = Read("machina_kuka_monitor.src"),
            ["machina_kuka_monitor.dat"] = Read("machina_kuka_monitor.dat"),
            ["machina_kuka_monitor.xml"] = Fill(Read("machina_kuka_monitor.xml"), port + 1),
        };
    }

    /// <summary>One shipped file as embedded, placeholders unfilled.</summary>
    internal static string Read(string file) => DriverFiles.Read("kuka", file);
}
