namespace Machina;

/// <summary>
/// The actions a device driver sent (or adopted after a reconnect) whose acknowledgements it awaits, oldest first, and how
/// a controller's acknowledgement maps back to an action id. Shared by the drivers whose controllers acknowledge in order
/// (ABB, UR). Thread-safe: sends and the receive loop use it at the same time.
/// </summary>
internal sealed class AwaitedAcknowledgements(Func<int, int> wireId)
{
    private readonly Queue<int> _ids = new();

    /// <summary>Awaits the acknowledgement of an action, after those already awaited.</summary>
    internal void Expect(int actionId)
    {
        lock (_ids)
        {
            _ids.Enqueue(actionId);
        }
    }

    /// <summary>
    /// The action id an acknowledgement with <paramref name="id"/> (as the controller knows it) stands for. The awaited action
    /// with that wire id is taken off the list with every action before it (the controller acknowledges in order; a skipped
    /// acknowledgement is covered by a later one). An id nobody awaits is returned unchanged, for the session to report.
    /// </summary>
    internal int Resolve(int id)
    {
        lock (_ids)
        {
            int index = 0, found = -1;
            foreach (int awaiting in _ids)
            {
                if (wireId(awaiting) == id)
                {
                    found = index;
                    break;
                }
                index++;
            }
            int actionId = id;
            for (int i = 0; i <= found; i++)
            {
                actionId = _ids.Dequeue();
            }
            return actionId;
        }
    }
}
