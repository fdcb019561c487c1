namespace Machina.Simulation.Rapid;

/// <summary>
/// Synchronization points of the tasks (RAPID Multitasking: WaitSyncTask): a task waits at a point, named by its syncident, until
/// every task of its task list waits at a point of the same name; then all of them go on.
/// </summary>
internal sealed partial class RapidTwinController
{
    private readonly object _syncGate = new();
    private readonly Dictionary<string, (long Round, HashSet<string> Waiting)> _syncPoints = new(StringComparer.OrdinalIgnoreCase);

    /// <summary>True when a task of that name is loaded (made by <see cref="Task"/>).</summary>
    internal bool HasTask(string name)
    {
        lock (_gate)
        {
            return _tasks.ContainsKey(name);
        }
    }

    /// <summary>
    /// <paramref name="task"/> waits at sync point <paramref name="id"/> for <paramref name="tasks"/>, up to <paramref name="seconds"/>
    /// (null: as long as it takes), serving its traps; false when the time ran out (it waits there no more).
    /// </summary>
    internal bool WaitSync(string id, RapidTask task, IReadOnlyCollection<string> tasks, double? seconds)
    {
        long round;
        lock (_syncGate)
        {
            (long Round, HashSet<string> Waiting) point = _syncPoints.TryGetValue(id, out var p) ? p : (0, new HashSet<string>(StringComparer.OrdinalIgnoreCase));
            point.Waiting.Add(task.Name);
            if (tasks.All(point.Waiting.Contains))
            {
                _syncPoints[id] = (point.Round + 1, new HashSet<string>(StringComparer.OrdinalIgnoreCase));
                Monitor.PulseAll(_syncGate);
                return true;
            }
            _syncPoints[id] = point;
            round = point.Round;
        }
        long start = Options.Time.GetTimestamp();
        while (true)
        {
            task.RunPendingTraps();
            lock (_syncGate)
            {
                if (_syncPoints[id].Round != round)
                {
                    return true;
                }
                if ((seconds is { } most && Options.Time.GetElapsedTime(start).TotalSeconds >= most) || task.CancellationToken.IsCancellationRequested)
                {
                    _syncPoints[id].Waiting.Remove(task.Name);
                    task.CancellationToken.ThrowIfCancellationRequested();
                    return false;
                }
                Twin.TwinWait.Blocking();
                Monitor.Wait(_syncGate, TimeSpan.FromMilliseconds(50));
            }
        }
    }
}
