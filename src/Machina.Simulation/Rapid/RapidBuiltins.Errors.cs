namespace Machina.Simulation.Rapid;

/// <summary>
/// Error recovery instructions (RAPID reference, "Error recovery"): ErrWrite and ErrLog write to the event log (the twin's
/// pendant), SkipWarn forgets the last warning, BookErrNo books a number for the program's own errors, ExitCycle ends the
/// cycle and starts main again.
/// </summary>
internal static partial class RapidBuiltins
{
    /// <summary>The first error number BookErrNo hands out (the manual's range for a program's own errors is 1..90).</summary>
    internal const int FirstBookedErrorNumber = 1;

    private static IEnumerable<RapidBuiltin> ErrorRecovery() =>
    [
        Instruction("ErrWrite", [Sw("W"), Sw("I"), P("Header", "string"), P("Reason", "string"), Opt("RL2", "string"), Opt("RL3", "string"), Opt("RL4", "string")], call =>
        {
            string kind = call.Has(0) ? "warning" : call.Has(1) ? "information" : "error";
            string text = string.Join(" ", Enumerable.Range(3, 4).Where(call.Has).Select(call.Str));
            Log(call, $"Event ({kind}, ErrWrite): {call.Str(2)}: {text}");
            // The event log's numbers of a program's own messages: 80001 error, 80002 warning, 80003 information.
            call.Machine.Task.Controller.LogEvent(call.Has(0) ? 80002 : call.Has(1) ? 80003 : 80001, call.Str(2));
        }),
        Instruction("ErrLog", [P("ErrorID", "num"), Sw("W"), Sw("I"), P("Argument1", null), P("Argument2", null), P("Argument3", null),
            P("Argument4", null), P("Argument5", null)], call =>
        {
            string kind = call.Has(1) ? "warning" : call.Has(2) ? "information" : "error";
            string arguments = string.Join(", ", Enumerable.Range(3, 5).Select(p => RapidValues.ToText(call.Value(p))));
            Log(call, $"Event {RapidValues.FormatNumber(call.Num(0))} ({kind}, ErrLog): {arguments}");
            call.Machine.Task.Controller.LogEvent((int)call.Num(0), RapidValues.ToText(call.Value(3)));
        }),
        Instruction("SkipWarn", [], _ => { }),
        Instruction("BookErrNo", [P("ErrorName", "errnum", true)], call => call.Set(0, (double)call.Machine.Task.Controller.BookErrorNumber())),
        Instruction("ResetRetryCount", [], call => call.Machine.ResetRetries()),
        Instruction("ExitCycle", [], call => throw new RapidExitCycleException(call.Line)),
    ];

    private static void Log(RapidCall call, string text)
    {
        RapidTwinController c = call.Machine.Task.Controller;
        c.Pendant.Log(c.TaskLabel(call.Machine.Task) + text);
        c.Arm.Record(call.Line, Twin.TwinTraceKind.Message, text);
    }
}

/// <summary>ExitCycle: the current cycle ends (UNDO handlers run) and the task starts its main routine again, keeping its data.</summary>
internal sealed class RapidExitCycleException(int line) : Exception($"ExitCycle at line {line}")
{
    /// <summary>The line of the ExitCycle.</summary>
    public int Line { get; } = line;
}
