using System.Globalization;
using System.Text;

namespace Machina.Simulation.Rapid;

/// <summary>One compared step: what the library's cursor expects and what the RAPID twin did.</summary>
/// <param name="Index">1-based number of the step (motions and outputs, in order).</param>
/// <param name="Action">The action, as an instruction (null when the twin did a step the actions do not have).</param>
/// <param name="Line">The module line the twin ran for it (0 when it did not run it).</param>
/// <param name="Expected">The cursor's state after the action, in words.</param>
/// <param name="Actual">The twin's state after the step, in words.</param>
/// <param name="Problem">Why they differ, or null when they agree.</param>
internal sealed record RapidVerifyStep(int Index, string? Action, int Line, string Expected, string Actual, string? Problem);

/// <summary>The result of running a compiled RAPID program on the twin and comparing it with the library's cursor.</summary>
internal sealed class RapidVerification
{
    /// <summary>Each compared step, in order.</summary>
    public List<RapidVerifyStep> Steps { get; } = [];

    /// <summary>How the program ended on the twin.</summary>
    public RapidProgramState State { get; init; }

    /// <summary>The controller's load or execution error, or null.</summary>
    public string? Error { get; init; }

    /// <summary>Program time on the twin, in seconds.</summary>
    public double Seconds { get; init; }

    /// <summary>True when the program ran to its end and every step agrees.</summary>
    public bool Passed => State == RapidProgramState.Finished && Steps.All(s => s.Problem is null);

    /// <summary>A one-line summary.</summary>
    public string Summary => Passed
        ? string.Create(CultureInfo.InvariantCulture, $"OK: {Steps.Count} steps agree; the program runs in {Seconds:0.###} s")
        : Error is not null
            ? $"FAILED: {Error}"
            : $"FAILED: {Steps.Count(s => s.Problem is not null)} of {Steps.Count} steps differ";

    /// <summary>The report, one line per step.</summary>
    public string ToText()
    {
        var text = new StringBuilder();
        foreach (RapidVerifyStep step in Steps)
        {
            text.Append(CultureInfo.InvariantCulture, $"{step.Index,4} line {step.Line,-5} {(step.Problem is null ? "ok  " : "DIFF")} {step.Action}").Append('\n');
            if (step.Problem is not null)
            {
                text.Append("       expected ").Append(step.Expected).Append('\n')
                    .Append("       twin     ").Append(step.Actual).Append('\n')
                    .Append("       ").Append(step.Problem).Append('\n');
            }
        }
        return text.Append(Summary).Append('\n').ToString();
    }
}
