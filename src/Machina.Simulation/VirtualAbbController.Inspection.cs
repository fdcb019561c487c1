namespace Machina.Simulation;

public sealed partial class VirtualAbbController
{
    private int _monitorReportsSent;

    /// <summary>How many state reports (<c>$24</c>) have been sent on the monitor port.</summary>
    public int MonitorReportsSent => Volatile.Read(ref _monitorReportsSent);

    /// <summary>Time between two monitor reports now (changed by instruction 103).</summary>
    public TimeSpan MonitorPeriod
    {
        get
        {
            lock (Gate)
            {
                return _monitorPeriod;
            }
        }
    }
}
