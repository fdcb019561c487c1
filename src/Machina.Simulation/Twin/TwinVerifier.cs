namespace Machina.Simulation.Twin;

/// <summary>
/// Verifying a compiled program on a twin, for any language: the cursor's expected steps, the arm started at the first
/// motion's target, the program run on a new twin controller, and the step-by-step comparison of the arm's trace. A language's
/// verifier gives only its specifics: tolerances, how it writes an output, how it makes its controller and which states mean
/// finished, and (in <see cref="Verify"/>) how it loads and runs the program.
/// </summary>
/// <typeparam name="TOptions">The language's settings.</typeparam>
/// <typeparam name="TController">The language's twin controller.</typeparam>
/// <typeparam name="TState">The language's program state.</typeparam>
internal sealed class TwinVerifier<TOptions, TController, TState>
    where TOptions : TwinOptions
    where TController : TwinController<TOptions, TState>
    where TState : struct, Enum
{
    /// <summary>The tolerances and how outputs compare.</summary>
    public required TwinComparison Comparison { get; init; }

    /// <summary>The text the twin traces for an output the language's compiler writes (null: it writes none for that action).</summary>
    public required Func<RobotAction, string?> OutputOf { get; init; }

    /// <summary>Makes the language's controller.</summary>
    public required Func<TOptions, TController> Create { get; init; }

    /// <summary>The state of a program that ran to its end.</summary>
    public required TState Finished { get; init; }

    /// <summary>Which entries of the arm's trace are the program's steps (all by default).</summary>
    public Func<TwinTraceEntry, bool> IsStep { get; init; } = static _ => true;

    /// <summary>The warnings the controller logged while the program ran (none by default).</summary>
    public Func<TController, IEnumerable<string>> Warnings { get; init; } = static _ => [];

    /// <summary>
    /// Runs a program on a controller with <paramref name="options"/> (its arm started where the first motion of
    /// <paramref name="actions"/> goes) and compares it with them; <paramref name="run"/> loads and runs the program and gives how
    /// it ended with the controller's error (a refused load ends it Failed, with the load's message).
    /// </summary>
    public TwinVerification<TState> Verify(TOptions options, IEnumerable<RobotAction> actions, Func<TController, (TState State, string? Error)> run)
    {
        List<TwinExpectation> expected = TwinComparison.Expect(actions, options.Model, OutputOf);
        options = options with { StartJoints = TwinComparison.StartOf(expected, options.Model, options.StartJoints) ?? options.StartJoints };
        TController twin = Create(options);
        try
        {
            (TState state, string? error) = run(twin);
            var result = new TwinVerification<TState> { State = state, Finished = EqualityComparer<TState>.Default.Equals(state, Finished), Error = error, Seconds = twin.Clock.Seconds };
            result.Warnings.AddRange(Warnings(twin));
            Comparison.Fill(result, expected, twin.Arm.Trace.Where(IsStep));
            return result;
        }
        finally
        {
            (twin as IDisposable)?.Dispose();
        }
    }
}
