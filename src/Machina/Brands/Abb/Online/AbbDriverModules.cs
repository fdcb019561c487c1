namespace Machina;

/// <summary>
/// The RAPID driver and monitor modules Machina ships (drivers/abb), with the server address filled in
/// (spec online §6.9): driver on <c>port</c>, monitor on <c>port + 1</c>.
/// </summary>
internal static class AbbDriverModules
{
    /// <summary>Default monitor report rate in Hz (the original reported at 10 Hz).</summary>
    public const double DefaultMonitorRate = 50;

    /// <summary>The four files (driver .mod/.pgf, monitor .mod/.pgf) by file name, ready to load on the controller.</summary>
    public static IReadOnlyDictionary<string, string> Create(string host, int port, double monitorRateHz = DefaultMonitorRate)
    {
        ArgumentException.ThrowIfNullOrWhiteSpace(host);
        if (host.Length > 80 || host.Any(c => c == '"' || c > 126 || char.IsControl(c) || char.IsWhiteSpace(c)))
        {
            throw new ArgumentException($"\"{host}\" is not an address the RAPID driver can listen on.", nameof(host));
        }
        if (port < 1 || port > 65534)
        {
            throw new ArgumentOutOfRangeException(nameof(port), port, "The driver port must be between 1 and 65534 (the monitor uses port + 1).");
        }
        if (!(monitorRateHz > 0 && monitorRateHz <= 250))
        {
            throw new ArgumentOutOfRangeException(nameof(monitorRateHz), monitorRateHz, "The monitor rate must be between 0 and 250 reports per second.");
        }
        string interval = Num.F(1 / monitorRateHz, 3);
        string Fill(string text, int p) =>
            DriverFiles.Fill(text, ("HOSTNAME", host), ("PORT", p.ToString(Num.Inv)), ("MONITOR_INTERVAL", interval));
        return new Dictionary<string, string>
        {
            ["machina_abb_driver.mod"] = Fill(Read("machina_abb_driver.mod"), port),
            ["machina_abb_driver.pgf"] = Read("machina_abb_driver.pgf"),
            ["machina_abb_monitor.mod"] = Fill(Read("machina_abb_monitor.mod"), port + 1),
            ["machina_abb_monitor.pgf"] = Read("machina_abb_monitor.pgf"),
        };
    }

    private static string Read(string file) => DriverFiles.Read("abb", file);
}
