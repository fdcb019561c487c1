namespace Machina.Simulation.Rapid;

/// <summary>One call of a routine: its local data (parameters passed by reference share the caller's cell) and its state.</summary>
internal sealed class RapidFrame(RapidRoutine routine, RapidCell[] cells)
{
    /// <summary>The routine.</summary>
    public RapidRoutine Routine { get; } = routine;

    /// <summary>The local cells, by slot.</summary>
    public RapidCell[] Cells { get; } = cells;

    /// <summary>The value a FUNC returned.</summary>
    public object? ReturnValue { get; set; }

    /// <summary>The label a GOTO jumps to.</summary>
    public string? GotoLabel { get; set; }

    /// <summary>The error the ERROR handler is taking, or null.</summary>
    public RapidRuntimeException? Handling { get; set; }
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
