namespace Machina.Simulation.Rapid;

/// <summary>A module the controller refuses to load (syntax, unknown name, type error), with the module's line.</summary>
internal sealed class RapidLoadException(int line, string message) : Exception($"Load error: line {line}: {message}")
{
    /// <summary>The 1-based line of the module where the error is.</summary>
    public int Line { get; } = line;

    /// <summary>The reason alone, without the line.</summary>
    public string Reason { get; } = message;

    /// <summary>The module the error is in (null when unknown).</summary>
    public string? Module { get; init; }

    /// <summary>A syntax error message.</summary>
    public static string Syntax(string what) => $"Syntax error: {what}";

    /// <summary>A reference error message (an unknown or misused name).</summary>
    public static string Reference(string what) => $"Reference error: {what}";

    /// <summary>A type error message.</summary>
    public static string Type(string what) => $"Type error: {what}";
}

/// <summary>
/// A RAPID run-time error with its error number (<c>ERRNO</c>): an error handler of the routine may take it; otherwise it stops
/// the task with the controller's message.
/// </summary>
internal sealed class RapidRuntimeException(int errno, int line, string message) : Exception($"Execution error: line {line}: {message}")
{
    /// <summary>The RAPID error number (an <c>ERR_…</c> constant, or a user's own).</summary>
    public int ErrorNumber { get; } = errno;

    /// <summary>The line where the error happened.</summary>
    public int Line { get; } = line;

    /// <summary>The reason alone, without the line.</summary>
    public string Reason { get; } = message;

    /// <summary>The controller's event number for the event log (e.g. 50050 for a motion error), or 0.</summary>
    public int Event { get; init; }

    /// <summary>
    /// True for an error of the system error handler: a budget of the twin (steps, stack, calls, arrays), or an error inside an
    /// ERROR handler. No ERROR handler takes it, the task stops.
    /// </summary>
    public bool Fatal { get; init; }

    /// <summary>The routine frame that passed this error on with <c>RAISE</c> (its own handler must not take it again).</summary>
    internal object? RaisedBy { get; set; }
}
