namespace Machina.Simulation.Twin;

/// <summary>
/// What every language's twin controller is made of: its settings, its clock, the arm, the pendant, and how its last program
/// run stands (<see cref="State"/> and <see cref="Error"/>). A language adds how it loads and runs programs; a fourth language
/// is a folder with its interpreter and a controller derived from this one.
/// </summary>
/// <typeparam name="TOptions">The language's settings.</typeparam>
/// <typeparam name="TState">The language's program state.</typeparam>
internal abstract class TwinController<TOptions, TState>
    where TOptions : TwinOptions
    where TState : struct, Enum
{
    /// <summary>
    /// A controller with <paramref name="options"/>; <paramref name="interpolates"/>: its arm moves along the path in real time;
    /// <paramref name="movesWhileServing"/>: the arm goes on moving while an interrupt routine runs (KUKA), until it brakes.
    /// </summary>
    protected TwinController(TOptions options, bool interpolates, bool movesWhileServing = false)
    {
        Options = options;
        Clock = new TwinClock(options.Time, options.RealTime);
        Arm = new TwinArm(options.Model, options.StartJoints, Clock) { MaxTrace = options.MaxTrace, Interpolates = interpolates, MovesWhileServing = movesWhileServing };
    }

    /// <summary>The settings.</summary>
    public TOptions Options { get; }

    /// <summary>The controller's clock.</summary>
    public TwinClock Clock { get; }

    /// <summary>The arm.</summary>
    public TwinArm Arm { get; }

    /// <summary>The pendant: program messages, the event log or logbook, errors.</summary>
    public TwinPendant Pendant { get; } = new();

    /// <summary>Where the program is: Running while it runs, else how the last run ended.</summary>
    public TState State => ProgramStatus.State;

    /// <summary>The message of the load, compile or runtime error that stopped the last run (null when none did).</summary>
    public string? Error => ProgramStatus.Error;

    /// <summary>The state and error, written by the language's controller.</summary>
    protected TwinProgramStatus<TState> ProgramStatus { get; } = new();
}
