using System.Collections.Concurrent;

namespace Machina.Tests.Online;

/// <summary>Records what a brand's driver reports, the controller's failure report above all (ABB and KUKA failure tests).</summary>
internal sealed class FailureRecordingListener : IDeviceListener
{
    internal TaskCompletionSource<(int Id, string Reason, string? Code)> Failed { get; } = new(TaskCreationOptions.RunContinuationsAsynchronously);

    internal ConcurrentQueue<int> Acknowledged { get; } = new();

    internal ConcurrentQueue<MachinaException> Faults { get; } = new();

    public void OnAcknowledged(int id) => Acknowledged.Enqueue(id);

    public void OnMotion(in MotionSample sample)
    {
    }

    public void OnStopped(MachinaException reason) => Faults.Enqueue(reason);

    public void OnResumed()
    {
    }

    public void OnFailed(int id, string reason, string? code) => Failed.TrySetResult((id, reason, code));

    public void OnFailedAfter(int executedId, string reason, string? code) => FailedAfter.TrySetResult((executedId, reason, code));

    /// <summary>A failure named by how far the program got (UR).</summary>
    internal TaskCompletionSource<(int ExecutedId, string Reason, string? Code)> FailedAfter { get; } = new(TaskCreationOptions.RunContinuationsAsynchronously);

    public void OnFault(MachinaException error) => Faults.Enqueue(error);
}
