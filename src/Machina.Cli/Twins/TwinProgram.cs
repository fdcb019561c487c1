using Machina.Simulation.Twin;

namespace Machina.Cli.Twins;

/// <summary>
/// What <see cref="ITwinProgram"/> does the same for every language: its names, which compiled files it loads, and running or
/// verifying a program on a new twin of a model (settings with the model and limits, load, run, the outcome). A language gives
/// how it makes its controller, loads and starts a program, and which verifier checks it.
/// </summary>
/// <typeparam name="TOptions">The language's settings.</typeparam>
/// <typeparam name="TController">The language's twin controller.</typeparam>
/// <typeparam name="TState">The language's program state.</typeparam>
internal abstract class TwinProgram<TOptions, TController, TState>(BrandDefinition brand, string language, string article, string jointsWord,
    string? programNoun, TState finished, params string[] loads) : ITwinProgram
    where TOptions : TwinOptions, new()
    where TController : TwinController<TOptions, TState>
    where TState : struct, Enum
{
    public BrandDefinition Brand => brand;

    public string Language => language;

    public string Article => article;

    public string JointsWord => jointsWord;

    public string? ProgramNoun => programNoun;

    public abstract Func<CliArgs, RobotModel, System.Net.IPAddress, CliContext, Task<int>>? RunLoaded { get; }

    public virtual IReadOnlyList<string> LoadOptions => [];

    public virtual bool LoadsSeveral => false;

    public abstract bool IsProgram(string fullPath);

    public abstract IReadOnlyList<string> ProgramFiles(string fullPath);

    public bool Loads(RobotProgramFile file) => loads.Any(e => file.Extension.Equals(e, StringComparison.OrdinalIgnoreCase));

    public TwinCheck Verify(IReadOnlyList<(string Name, string Text)> files, List<RobotAction> actions, RobotModel model, TwinLimits limits, CancellationToken cancellation)
    {
        TwinVerification<TState> result = Verify(files, actions, Options(model, limits), cancellation);
        return new TwinCheck(result.Passed, result.ToText);
    }

    public TwinRun Run(IReadOnlyList<(string Name, string Text)> files, RobotModel model, TwinLimits limits, CancellationToken cancellation)
    {
        TOptions options = Options(model, limits);
        TController twin = Create(options);
        try
        {
            try
            {
                Load(twin, files);
            }
            catch (Exception e) when (Refusal(e) is not null)
            {
                return TwinRun.Refused(Refusal(e)!);
            }
            TState state = RunMain(twin, files, cancellation);
            return new TwinRun(null, EqualityComparer<TState>.Default.Equals(state, finished), twin.Error, [.. twin.Arm.Trace], twin.Clock.Seconds, options.StartJoints);
        }
        finally
        {
            (twin as IDisposable)?.Dispose();
        }
    }

    /// <summary>The language's verifier run on <paramref name="files"/> with <paramref name="options"/>.</summary>
    protected abstract TwinVerification<TState> Verify(IReadOnlyList<(string Name, string Text)> files, List<RobotAction> actions, TOptions options, CancellationToken cancellation);

    /// <summary>A new controller with <paramref name="options"/>.</summary>
    protected abstract TController Create(TOptions options);

    /// <summary>Loads <paramref name="files"/> on <paramref name="twin"/> (a script language loads nothing before it runs).</summary>
    protected abstract void Load(TController twin, IReadOnlyList<(string Name, string Text)> files);

    /// <summary>For the exception of a refused load, the controller's message (null for any other exception).</summary>
    protected abstract string? Refusal(Exception e);

    /// <summary>Runs the loaded program's main routine (or the script) to its end, and gives how it ended.</summary>
    protected abstract TState RunMain(TController twin, IReadOnlyList<(string Name, string Text)> files, CancellationToken cancellation);

    private static TOptions Options(RobotModel model, TwinLimits limits) => new() { Model = model, Limits = limits };
}
