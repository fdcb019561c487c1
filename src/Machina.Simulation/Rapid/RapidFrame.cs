namespace Machina.Simulation.Rapid;

/// <summary>
/// One call of a routine: its local data (parameters passed by reference share the caller's cell) and its state. A call that returned
/// normally leaves its frame to the routine's next call (<see cref="RapidRoutine.KeepSpareFrame"/>): the frame, its slot array and
/// the cells it owns are made once per routine instead of at every call, and every slot is given its value again at the call.
/// </summary>
internal sealed class RapidFrame(RapidRoutine routine)
{
    /// <summary>The cells this frame made (a by-reference parameter's slot holds the caller's cell instead, never one of these).</summary>
    private readonly RapidCell?[] _own = new RapidCell?[routine.FrameSize];

    /// <summary>The routine.</summary>
    public RapidRoutine Routine { get; } = routine;

    /// <summary>The local cells, by slot.</summary>
    public RapidCell[] Cells { get; } = new RapidCell[routine.FrameSize];

    /// <summary>The value a FUNC returned.</summary>
    public object? ReturnValue { get; set; }

    /// <summary>The label a GOTO jumps to.</summary>
    public string? GotoLabel { get; set; }

    /// <summary>The error the ERROR handler is taking, or null.</summary>
    public RapidRuntimeException? Handling { get; set; }

    /// <summary>
    /// Puts this frame's own cell into <paramref name="slot"/> with <paramref name="value"/>; the cell is made at the slot's first use
    /// (a slot is always the same parameter, datum or FOR variable of the routine, so its name, type and storage never change).
    /// </summary>
    public RapidCell Own(int slot, string name, RapidDataType type, RapidStorage storage, object value)
    {
        RapidCell? cell = _own[slot];
        if (cell is null)
        {
            cell = _own[slot] = new RapidCell(name, type, storage, value);
        }
        else
        {
            cell.Value = value;
        }
        Cells[slot] = cell;
        return cell;
    }

    /// <summary>
    /// The record datum <paramref name="slot"/> held at the routine's last call, given its initial value again (RAPID reference,
    /// "Data declarations": a routine's VAR data get their initial values at each call), or null when there is none: the record of
    /// a PROC's or TRAP's VAR datum without an initial value is its own until the call returns (every value it is given is a copy or
    /// a new aggregate, a routine that takes it as an IN parameter has returned, and a PROC returns no value), so the next call can
    /// use it again instead of a new one (our driver's ExecuteNext: <c>VAR MachinaRequest r</c>, 14 components, at every request).
    /// A FUNC's datum may be the value it returned, which its caller may still hold: never for a FUNC (the caller checks).
    /// </summary>
    public RapidRecord? KeptRecord(int slot, RapidDataType type)
    {
        if (_own[slot] is { Storage: RapidStorage.Var, Value: RapidRecord kept } && type.Rank == 0 && kept.Type == type.Element)
        {
            RapidValues.ResetToDefault(kept);
            return kept;
        }
        return null;
    }

    /// <summary>True when <paramref name="slot"/> holds this frame's own cell (not data of a caller passed by reference).</summary>
    public bool HoldsOwn(int slot) => ReferenceEquals(Cells[slot], _own[slot]);

    /// <summary>Clears the state of the call that returned, before the frame serves the routine's next call.</summary>
    public void Reuse()
    {
        ReturnValue = null;
        GotoLabel = null;
        Handling = null;
    }
}

/// <summary>How a statement ended.</summary>
internal enum RapidFlow
{
    /// <summary>Go on with the next statement.</summary>
    Next,

    /// <summary>RETURN: leave the routine.</summary>
    Return,

    /// <summary>GOTO: find the label.</summary>
    Goto,

    /// <summary>RETRY (error handler): run the failed statement again.</summary>
    Retry,

    /// <summary>TRYNEXT (error handler): go on after the failed statement.</summary>
    TryNext,
}

/// <summary>The program ends (EXIT) or stops (Stop): unwinds every routine of the task.</summary>
internal sealed class RapidHaltException(bool exit, int line) : Exception(exit ? "EXIT" : "Stop")
{
    /// <summary>True for EXIT (the program ends), false for Stop.</summary>
    public bool Exit { get; } = exit;

    /// <summary>The line of the EXIT or Stop.</summary>
    public int Line { get; } = line;
}
