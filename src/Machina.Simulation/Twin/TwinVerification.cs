using System.Globalization;
using System.Text;

namespace Machina.Simulation.Twin;

/// <summary>One compared step: what the library's cursor expects and what the twin controller did.</summary>
/// <param name="Index">1-based number of the step (motions and outputs, in order).</param>
/// <param name="Action">The action, as an instruction (null when the twin did a step the actions do not have).</param>
/// <param name="Line">The program line (script or module line) the twin ran for it (0 when it did not run it).</param>
/// <param name="Expected">The cursor's state after the action, in words.</param>
/// <param name="Actual">The twin's state after the step, in words.</param>
/// <param name="Problem">Why they differ, or null when they agree.</param>
/// <param name="Source">The action itself (null when the twin did a step the actions do not have), so that a caller can name its source line.</param>
/// <param name="Reached">True when the twin ran this step (false: the program ended or stopped before it).</param>
internal sealed record TwinVerifyStep(int Index, string? Action, int Line, string Expected, string Actual, string? Problem,
    RobotAction? Source = null, bool Reached = true);

/// <summary>
/// The result of running a compiled program on a twin controller (any language) and comparing it with the library's
/// cursor. <typeparamref name="TState"/> is the language's program state (how the program ended).
/// </summary>
internal sealed class TwinVerification<TState>
    where TState : struct, Enum
{
    /// <summary>Each compared step, in order.</summary>
    public List<TwinVerifyStep> Steps { get; } = [];

    /// <summary>How the program ended on the twin.</summary>
    public TState State { get; init; }

    /// <summary>True when the program ran to its end (the language's "finished" state).</summary>
    public bool Finished { get; init; }

    /// <summary>The controller's load, compile or runtime error, or null.</summary>
    public string? Error { get; init; }

    /// <summary>The warnings the controller logged while the program ran (UR: overlapping blends), in order.</summary>
    public List<string> Warnings { get; } = [];

    /// <summary>Program time on the twin, in seconds.</summary>
    public double Seconds { get; init; }

    /// <summary>True when the program ran to its end and every step agrees.</summary>
    public bool Passed => Finished && Steps.All(s => s.Problem is null);

    /// <summary>A one-line summary.</summary>
    public string Summary => Passed
        ? string.Create(CultureInfo.InvariantCulture, $"OK: {Counted.Of(Steps.Count, "step")} {(Steps.Count == 1 ? "agrees" : "agree")}; the program runs in {Seconds:0.###} s")
        : Error is not null
            ? $"FAILED: {Error}"
            : $"FAILED: {Steps.Count(s => s.Problem is not null)} of {Counted.Of(Steps.Count, "step")} differ";

    /// <summary>
    /// The report, one line per step: the line of the program file that holds each action when <paramref name="sourceLine"/> gives
    /// it (a .machina file's line; else the compiled program's line the twin ran), and "not reached" for a step the program never
    /// got to.
    /// </summary>
    public string ToText(Func<RobotAction, int?>? sourceLine = null)
    {
        var text = new StringBuilder();
        foreach (TwinVerifyStep step in Steps)
        {
            int? line = step.Source is { } action && sourceLine is not null ? sourceLine(action) : null;
            string where = line is int l ? $"line {l,-5}" : step.Reached ? $"line {step.Line,-5}" : "line ?    ";
            string status = !step.Reached ? "not reached" : step.Problem is null ? "ok  " : "DIFF";
            text.Append(CultureInfo.InvariantCulture, $"{step.Index,4} {where} {status} {step.Action}").Append('\n');
            if (step.Problem is not null && step.Reached)
            {
                text.Append("       expected ").Append(step.Expected).Append('\n')
                    .Append("       twin     ").Append(step.Actual).Append('\n')
                    .Append("       ").Append(step.Problem).Append('\n');
            }
        }
        foreach (string warning in Warnings)
        {
            text.Append("controller: ").Append(warning).Append('\n');
        }
        return text.Append(Summary).Append('\n').ToString();
    }
}
