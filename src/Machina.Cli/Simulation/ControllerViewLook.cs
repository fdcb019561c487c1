namespace Machina.Cli.Simulation;

/// <summary>
/// One <see cref="ControllerView"/> (a controller's logs copied whole at one moment) read as a look: a log's count is its
/// length (requests: the view's count received), and what came since a count is its last entries past it. Every view is a new
/// mark for the outputs, so they are compared at each look.
/// </summary>
internal sealed class ControllerViewLook(ControllerView view) : IControllerLook
{
    /// <inheritdoc/>
    public int RequestsExecuted => view.RequestsExecuted;

    /// <inheritdoc/>
    public (object? Signals, long Writes) OutputsMark => (view, 0);

    /// <inheritdoc/>
    public long RequestsSince(long seen, ICollection<string> into) => Since(view.Requests, view.RequestsReceived, seen, into);

    /// <inheritdoc/>
    public long ExecutedIdsSince(long seen, ICollection<int> into) => Since(view.ExecutedIds, view.ExecutedIds.Count, seen, into);

    /// <inheritdoc/>
    public long PendantSince(long seen, ICollection<string> into) => Since(view.Pendant, view.Pendant.Count, seen, into);

    /// <inheritdoc/>
    public long ErrorsSince(long seen, ICollection<string> into) => Since(view.Errors, view.Errors.Count, seen, into);

    /// <inheritdoc/>
    public Machina.Simulation.Twin.TwinChangeSignal? Changes => null;

    /// <inheritdoc/>
    public ControllerRobot Robot() => new(view.Position, view.Joints, view.DigitalOutputs, view.AnalogOutputs);

    /// <summary>The last entries of <paramref name="kept"/> past <paramref name="seen"/> of <paramref name="total"/>.</summary>
    private static long Since<T>(IReadOnlyList<T> kept, long total, long seen, ICollection<T> into)
    {
        long fresh = Math.Clamp(total - seen, 0, kept.Count);
        for (int k = kept.Count - (int)fresh; k < kept.Count; k++)
        {
            into.Add(kept[k]);
        }
        return total;
    }
}
