using Machina.Simulation.Twin;

namespace Machina.Benchmarks.Differential;

/// <summary>How a run of a program on a twin ended.</summary>
internal enum TwinRunEnd
{
    /// <summary>The program ran to its end.</summary>
    Finished,

    /// <summary>The controller stopped the program (an unreachable target, a joint limit, an error).</summary>
    Stopped,

    /// <summary>The host's pre-check refused the program before anything was sent: the driver cannot stream an action.</summary>
    Refused,

    /// <summary>The host's pre-check refused the program before anything was sent: a target is out of the arm's reach.</summary>
    Unreachable,
}

/// <summary>
/// One run of a program on a twin: how it ended, why, and the motions and outputs the twin's arm did, in order (the steps the
/// two runs compare).
/// </summary>
/// <param name="End">How it ended.</param>
/// <param name="Why">The controller's error or the pre-check's refusal; null when it finished.</param>
/// <param name="Action">The 0-based index of the action the pre-check or the online run stopped at; null when unknown or finished.</param>
/// <param name="Steps">The motions and outputs of the twin's trace.</param>
internal sealed record TwinRun(TwinRunEnd End, string? Why, int? Action, IReadOnlyList<TwinTraceEntry> Steps)
{
    /// <summary>The motions and outputs of <paramref name="trace"/>.</summary>
    internal static List<TwinTraceEntry> StepsOf(IEnumerable<TwinTraceEntry> trace) =>
        [.. trace.Where(e => e.Kind is TwinTraceKind.Motion or TwinTraceKind.Output)];
}
