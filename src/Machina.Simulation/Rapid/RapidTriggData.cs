namespace Machina.Simulation.Rapid;

/// <summary>
/// A <c>triggdata</c>: the event that TriggIO, TriggEquip or TriggInt defined, which a later TriggL or TriggJ fires at its point of
/// the path (RAPID reference, "triggdata"); null until one of them ran.
/// </summary>
internal sealed class RapidTriggData
{
    /// <summary>The event, or null.</summary>
    public RapidTriggEvent? Event { get; set; }
}

/// <summary>
/// Where on a Trigg move an event fires and what it does. <paramref name="Distance"/> is mm from the end point (from the start with
/// <paramref name="FromStart"/>), or seconds before the end point with <paramref name="IsTime"/>; <paramref name="ShiftSeconds"/> moves
/// it later (\DODelay) or earlier (TriggEquip's EquipLag, negative). An output event sets <paramref name="Signal"/> (bank, index) to
/// <paramref name="Value"/>, or to 0 when <paramref name="Inhibit"/> reads TRUE then; an interrupt event orders interrupt
/// <paramref name="Interrupt"/>.
/// </summary>
internal sealed record RapidTriggEvent(double Distance, bool FromStart, bool IsTime, double ShiftSeconds, (string Name, string Bank, int Index)? Signal,
    double Value, int Interrupt, Func<bool>? Inhibit)
{
    /// <summary>TriggCheckIO: the signal compared (bank, index), the opnum relation (LT 1 … GT 6), the value, and \StopMove; null for other events.</summary>
    public (string Name, string Bank, int Index, int Relation, double Value, bool StopMove)? Check { get; init; }

    /// <summary>TriggSpeed: the analog output follows the TCP speed (mm/s) times <see cref="Value"/> from the event on.</summary>
    public bool FollowsSpeed { get; init; }

    /// <summary>\ProcID: the IPM process that gets the event (selector <see cref="Value"/>) instead of an output; null for none.</summary>
    public int? ProcId { get; init; }
}
