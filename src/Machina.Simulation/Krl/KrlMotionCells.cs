namespace Machina.Simulation.Krl;

/// <summary>
/// The system variables a motion reads ($BASE, $TOOL, $VEL, $ACC, $APO, $ADVANCE, $VEL_AXIS, $ACC_AXIS, the software limit
/// switches, and $TIMER and $TIMER_STOP for a timer's wake), found by name once when the controller is made: a motion read each of
/// them through the case-insensitive table of system variables, about fifteen look-ups an action. A system variable's cell is made with the controller and never replaced;
/// a program's write changes the value in the cell.
/// </summary>
internal sealed class KrlMotionCells(IReadOnlyDictionary<string, KrlCell> system)
{
    /// <summary>$BASE.</summary>
    public KrlCell Base { get; } = system["$BASE"];

    /// <summary>$TOOL.</summary>
    public KrlCell Tool { get; } = system["$TOOL"];

    /// <summary>$VEL.</summary>
    public KrlCell Vel { get; } = system["$VEL"];

    /// <summary>$ACC.</summary>
    public KrlCell Acc { get; } = system["$ACC"];

    /// <summary>$APO.</summary>
    public KrlCell Apo { get; } = system["$APO"];

    /// <summary>$ADVANCE.</summary>
    public KrlCell Advance { get; } = system["$ADVANCE"];

    /// <summary>$VEL_AXIS.</summary>
    public KrlCell VelAxis { get; } = system["$VEL_AXIS"];

    /// <summary>$ACC_AXIS.</summary>
    public KrlCell AccAxis { get; } = system["$ACC_AXIS"];

    /// <summary>$SOFTN_END.</summary>
    public KrlCell SoftMin { get; } = system["$SOFTN_END"];

    /// <summary>$SOFTP_END.</summary>
    public KrlCell SoftMax { get; } = system["$SOFTP_END"];

    /// <summary>$TIMER (its <see cref="KrlCell.Box"/> holds the values as last counted; reading <see cref="KrlCell.Value"/> counts first).</summary>
    public KrlCell Timer { get; } = system["$TIMER"];

    /// <summary>$TIMER_STOP.</summary>
    public KrlCell TimerStop { get; } = system["$TIMER_STOP"];
}
