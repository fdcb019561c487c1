namespace Machina;

/// <summary>
/// The three ports the host uses on a UR controller, found from the one given to Connect. A real controller takes scripts
/// on 30001-30003 and serves RTDE on 30004 and the dashboard on 29999. Any other script port P (a virtual controller on
/// OS-chosen ports) means RTDE on P + 1 and the dashboard on P + 2.
/// </summary>
/// <param name="Script">Where the driver script is sent (the port given to Connect).</param>
/// <param name="Rtde">Real-Time Data Exchange.</param>
/// <param name="Dashboard">Dashboard server.</param>
internal readonly record struct UrPorts(int Script, int Rtde, int Dashboard)
{
    /// <summary>The real controller's RTDE port.</summary>
    public const int StandardRtde = 30004;

    /// <summary>The real controller's dashboard port.</summary>
    public const int StandardDashboard = 29999;

    /// <summary>The script port the original Machina host used (the real-time client interface).</summary>
    public const int StandardScript = 30003;

    /// <summary>The ports for a script port given to Connect.</summary>
    public static UrPorts For(int scriptPort) => scriptPort is >= 30001 and <= 30003
        ? new UrPorts(scriptPort, StandardRtde, StandardDashboard)
        : new UrPorts(scriptPort, scriptPort + 1, scriptPort + 2);
}
