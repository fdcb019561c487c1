namespace Machina.Simulation;

public sealed partial class VirtualAbbController
{
    private int _monitorReportsSent;

    /// <summary>How many state reports (<c>$24</c>) the monitor task has sent on the monitor port.</summary>
    public int MonitorReportsSent => Volatile.Read(ref _monitorReportsSent);

    /// <summary>Time between two monitor reports now: the driver's <c>monitorUpdateInterval</c> (changed by request 103).</summary>
    public TimeSpan MonitorPeriod =>
        Twin is { } twin && twin.Persistents.TryGetValue("monitorUpdateInterval", out var cell) && cell.Value is double seconds && seconds > 0
            ? TimeSpan.FromSeconds(seconds)
            : _options.MonitorPeriod;
}
