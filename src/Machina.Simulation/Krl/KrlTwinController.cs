using Machina.Simulation.Twin;

namespace Machina.Simulation.Krl;

/// <summary>
/// A KUKA controller that runs KRL: <c>.src</c> and <c>.dat</c> files are loaded as the controller loads them (a mistake refuses
/// them with file and line), a main routine runs on the robot interpreter with the arm model's kinematics, and an error stops
/// the program with the controller's message.
/// </summary>
internal sealed partial class KrlTwinController : TwinController<KrlTwinOptions, KrlProgramState>, IDisposable
{
    private readonly Lock _gate = new();
    private readonly Dictionary<string, KrlModule> _modules = new(StringComparer.OrdinalIgnoreCase);
    private int _messageHandle;

    /// <summary>A controller with <paramref name="options"/> (KR 6 R900 sixx, not real-time, by default).</summary>
    public KrlTwinController(KrlTwinOptions? options = null)
        : base(options ?? new KrlTwinOptions(), interpolates: true, movesWhileServing: true)
    {
        KrlSystemVariables.AddTo(Environment, this);
        Motion = new KrlMotionCells(Environment.System);
        KrlBuiltins.AddTo(Environment);
        KrlBasicPackage.AddTo(Environment);
        KrlSystemVariables.AddMeasured(Environment, this);
        KrlSystemVariables.AddStatus(Environment, this);
        KrlProgramManagement.AddTo(Environment, this);
        AddEki();
        AddEkiCheck();
        AddRsi();
        AddRsiKrc2();
        foreach ((string name, int output) in Options.Signals)
        {
            if (output < 1 || output > KrlSystemVariables.DigitalCount)
            {
                throw new ArgumentException($"The signal {name} is mapped to $OUT[{output}], which does not exist (1 to {KrlSystemVariables.DigitalCount}).", nameof(options));
            }
            Environment.Signals[name] = new KrlCell(name, KrlType.Bool, false)
            {
                Read = () => Out(output),
                Written = _ => SignalWritten(name, output),
            };
        }
    }

    /// <summary>The system variables, signals and built-in routines.</summary>
    public KrlEnvironment Environment { get; } = new();

    /// <summary>The system variables a motion reads, found once.</summary>
    internal KrlMotionCells Motion { get; }

    /// <summary>The loaded modules, by name.</summary>
    public IReadOnlyDictionary<string, KrlModule> Modules => _modules;

    /// <summary>The main routine of the first file loaded (null before a load).</summary>
    public string? MainRoutine { get; private set; }

    /// <summary>
    /// Loads files (name with extension, text): each <c>.src</c> with the <c>.dat</c> of the same name. Throws
    /// <see cref="KrlLoadException"/> for the first syntax error, unknown name or type error; nothing is loaded then.
    /// </summary>
    public void Load(params (string Name, string Text)[] files) => Load(CancellationToken.None, files);

    /// <summary>
    /// Loads files as the overload without a token does, but stops with <see cref="OperationCanceledException"/> (nothing loaded)
    /// once <paramref name="cancellation"/> is cancelled, checked at each line: a caller's deadline covers the reading of a
    /// long file too.
    /// </summary>
    public void Load(CancellationToken cancellation, params (string Name, string Text)[] files)
    {
        foreach ((string name, string text) in files)
        {
            if (KrlMachineData.ListOf(name, text) is { } list)
            {
                Pendant.Log($"{name}: {list} is the controller's machine data (its Mada folder), not a program module: the twin keeps its own and does not load it");
            }
        }
        files = [.. files.Where(f => KrlMachineData.ListOf(f.Name, f.Text) is null)];
        var modules = new Dictionary<string, KrlModule>(_modules, StringComparer.OrdinalIgnoreCase);
        var data = new List<KrlDataList>();
        string? main = null;
        IReadOnlyDictionary<string, KrlType> types = KrlUserTypes.Collect(files);
        foreach ((string name, string text) in files)
        {
            string module = Path.GetFileNameWithoutExtension(name);
            string extension = Path.GetExtension(name).ToLowerInvariant();
            if (extension == ".dat")
            {
                KrlDataList list = KrlParser.ParseData(name, text, Options.Limits, types, cancellation);
                if (!string.Equals(list.Name, module, StringComparison.OrdinalIgnoreCase))
                {
                    throw new KrlLoadException(name, list.Line, $"DEFDAT {list.Name} must have the name of its file ({module})");
                }
                data.Add(list);
            }
            else if (extension is ".src" or ".sub")
            {
                var parsed = new KrlModule(module);
                // The first routine is the program even when it is not named after its file: published RSI programs ship as
                // ros_rsi.src with DEF RSI_AxisCorr( ), and their users select and run them so (kuka_experimental issue 48).
                KrlParser.ParseSource(name, text, parsed, Options.Limits, types, cancellation);
                modules[module] = parsed;
                main ??= extension == ".src" ? parsed.Routines[0].Name : null;
            }
            else
            {
                throw new KrlLoadException(name, 1, "the controller loads .src, .sub and .dat files");
            }
        }
        var binder = new KrlBinder(modules, Environment);
        foreach (KrlDataList list in data)
        {
            if (!modules.TryGetValue(list.Name, out KrlModule? module))
            {
                module = new KrlModule(list.Name);
                modules[list.Name] = module;
            }
            module.Externals.AddRange(list.Externals);
            foreach (KrlDeclaration declaration in list.Declarations)
            {
                if (module.Data.ContainsKey(declaration.Name))
                {
                    throw new KrlLoadException(list.File, declaration.Line, $"{declaration.Name} is declared twice in the data list");
                }
                object value = KrlValues.Default(declaration.Type);
                if (declaration.Initial is { } initial)
                {
                    binder.BindConstant(list.File, initial, declaration.Type);
                    value = KrlConvert.To(declaration.Type, new KrlMachine(this, default).Eval(initial, []), value);
                }
                module.Data[declaration.Name] = new KrlCell(declaration.Name, declaration.Type, value);
                if (declaration.Global)
                {
                    if (!list.IsPublic)
                    {
                        throw new KrlLoadException(list.File, declaration.Line, $"GLOBAL {declaration.Name} needs a PUBLIC data list (DEFDAT {list.Name} PUBLIC)");
                    }
                    module.GlobalData.Add(declaration.Name);
                }
            }
            InitialiseElements(list, module, binder);
        }
        cancellation.ThrowIfCancellationRequested();
        binder.BindAll();
        MarkWaitConditions(modules.Where(m => !_modules.TryGetValue(m.Key, out KrlModule? loaded) || !ReferenceEquals(loaded, m.Value)).Select(m => m.Value));
        foreach (KrlExternal external in modules.Values.SelectMany(m => m.Externals))
        {
            if (KrlBinder.FindRoutine(modules, null, external.Name) is null && !Environment.Builtins.ContainsKey(external.Name))
            {
                throw new KrlLoadException(external.File, external.Line, $"EXT {external.Name}: no routine of that name is loaded and the twin has no system routine {external.Name}");
            }
        }
        lock (_gate)
        {
            foreach ((string name, KrlModule module) in modules)
            {
                _modules[name] = module;
            }
            MainRoutine ??= main;
        }
    }

    /// <summary>Loads a <c>.src</c> file with its <c>.dat</c>, or every <c>.src</c> and <c>.dat</c> file of a folder.</summary>
    public void LoadFrom(string path) => Load([.. ProgramFiles(path).Select(f => (Path.GetFileName(f), ReadFile(f)))]);

    /// <summary>The text of program file <paramref name="file"/>, refused before it is read when it is larger than the limit allows.</summary>
    private string ReadFile(string file)
    {
        long most = Options.Limits.MaxProgramChars;
        return new FileInfo(file).Length > most
            ? throw new KrlLoadException(Path.GetFileName(file), 1, $"the file is larger than {most} bytes (the twin's limit)")
            : File.ReadAllText(file);
    }

    /// <summary>The files of a program path (see <see cref="LoadFrom"/>), <c>.src</c> files first.</summary>
    public static IReadOnlyList<string> ProgramFiles(string path)
    {
        if (Directory.Exists(path))
        {
            string[] sources = Directory.GetFiles(path, "*.src");
            Array.Sort(sources, StringComparer.Ordinal);
            string[] data = Directory.GetFiles(path, "*.dat");
            Array.Sort(data, StringComparer.Ordinal);
            return sources.Length > 0 ? [.. sources, .. data] : throw new FileNotFoundException($"The folder \"{path}\" has no .src file.");
        }
        string dat = Path.ChangeExtension(path, ".dat");
        return File.Exists(dat) && !string.Equals(dat, path, StringComparison.OrdinalIgnoreCase) ? [path, dat] : [path];
    }

    /// <summary>
    /// Runs <paramref name="entry"/> (default: the main routine of the first file loaded) to its END. HALT or cancellation stop it;
    /// an error stops it with the controller's message (also in the logbook).
    /// </summary>
    public KrlProgramState Run(string? entry = null, CancellationToken cancellation = default)
    {
        string name = entry ?? MainRoutine ?? "";
        KrlRoutine? routine = KrlBinder.FindRoutine(_modules, null, name);
        if (routine is null || routine.Parameters.Count > 0 || routine.ReturnType is not null)
        {
            return Finish(KrlProgramState.Failed, $"Program {name} not found: no subprogram without parameters of that name is loaded");
        }
        ProgramStatus.Set(KrlProgramState.Running, null);
        Interlocked.Exchange(ref _coincident, 0);
        Sends.Own(); // this thread runs the robot interpreter: what it sends on a held connection waits for its next wait
        var machine = new KrlMachine(this, cancellation) { Sends = Sends };
        Arm.Serve = machine.ServeInterrupts;
        Arm.NextWake = Clock.RealTime ? null : machine.ProgramTimeWake;
        try
        {
            machine.Run(routine);
            EndAdvanceRun(cancellation);
            return Finish(KrlProgramState.Finished, null);
        }
        catch (KrlResumeSignal resume)
        {
            return Finish(KrlProgramState.Failed, FormattableString.Invariant($"Impermissible program structure for RESUME: the program was in the routine that declared the interrupt ({resume.File}, line {resume.Line})"));
        }
        catch (KrlHaltException)
        {
            return Finish(KrlProgramState.Stopped, null);
        }
        catch (KrlRuntimeException ex)
        {
            return Finish(KrlProgramState.Failed, FormattableString.Invariant($"{ex.Message} ({ex.File ?? machine.File}, line {(ex.Line > 0 ? ex.Line : machine.Line)})"));
        }
        catch (OperationCanceledException)
        {
            return Finish(KrlProgramState.Stopped, null);
        }
        catch (Exception ex) when (ex is ArgumentException or InvalidCastException or ArithmeticException or IndexOutOfRangeException)
        {
            // What the binder and the built-ins do not catch yet (the fuzz run found a REAL where B_NOT needs an INT, angles past the
            // largest double): the program's error, never the process's.
            return Finish(KrlProgramState.Failed, FormattableString.Invariant($"the twin cannot run this statement: {ex.Message} ({machine.File}, line {machine.Line})"));
        }
        finally
        {
            Sends.Flush();
            Sends.Disown();
            EndRsi();
            Arm.Serve = null;
            Arm.NextWake = null;
        }
    }

    /// <summary>A new message handle for Set_KrlMsg.</summary>
    public int NextMessageHandle() => Interlocked.Increment(ref _messageHandle);

    private KrlProgramState Finish(KrlProgramState state, string? error)
    {
        Sends.Flush(); // whoever sees the run ended also got what it sent
        ProgramStatus.Set(state, error);
        if (error is not null)
        {
            Pendant.Log(error);
        }
        return state;
    }

    /// <inheritdoc/>
    public void Dispose()
    {
        EndRsi();
        CloseEki();
    }
}
