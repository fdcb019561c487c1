namespace Machina.Simulation;

public sealed partial class VirtualKukaController
{
    /// <summary>
    /// The acknowledgement entries (<see cref="_acks"/>) of actions the controller's buffer dropped in a restart while the
    /// driver still held them in its ring: the driver may run them (with nobody connected, before it is reset), and then they
    /// are logged executed here, as nobody else will. Guarded by the gate.
    /// </summary>
    private readonly HashSet<TaskCompletionSource<TwinAck>> _dropped = [];

    /// <summary>
    /// The buffer dropped <paramref name="request"/> (a restart lost it). While the driver has not run it, it is marked, and
    /// whoever takes its entry then (the driver's acknowledgement, its progress after the restart) logs it executed without
    /// waiting for the buffer. When the driver's answer was already taken, it is settled as it arrives.
    /// </summary>
    private protected override void Dropped(object request)
    {
        if (request is not TwinAction action)
        {
            return;
        }
        bool held;
        lock (Gate)
        {
            held = _acks.TryGetValue(action.Id, out TaskCompletionSource<TwinAck>? entry) && ReferenceEquals(entry, action.Acknowledged);
            if (held)
            {
                _dropped.Add(action.Acknowledged);
            }
        }
        if (!held)
        {
            _ = action.Acknowledged.Task.ContinueWith(answer => SettleDropped(action.Id, answer), CancellationToken.None,
                TaskContinuationOptions.ExecuteSynchronously, TaskScheduler.Default);
        }
    }

    /// <summary>The driver's answer to an action the buffer dropped: logged executed when it ran; whoever waits for it goes on.</summary>
    private void SettleDropped(int id, Task<TwinAck> answer)
    {
        if (!answer.IsCompletedSuccessfully)
        {
            return;
        }
        TwinAck ack = answer.Result;
        if (!ack.Lost && ack.Failure is null)
        {
            RanOutsideBuffer(id);
        }
        ack.Done.TrySetResult(false);
    }

    /// <summary>True (and forgotten) when the buffer dropped the action of <paramref name="entry"/>; call it under the gate.</summary>
    private bool TakeDropped(TaskCompletionSource<TwinAck>? entry) => entry is not null && _dropped.Remove(entry);
}
