using System.Xml.Linq;
using Machina.Simulation.Twin;

namespace Machina.Simulation.Rapid;

/// <summary>
/// An ABB controller that runs RAPID: modules are loaded into a task the way the controller loads them (a mistake refuses the
/// module, with its line), <c>main</c> runs on the twin arm with the model's kinematics, and an error that no handler takes
/// stops the task with the controller's message, as in the event log.
/// </summary>
internal sealed partial class RapidTwinController : TwinController<RapidTwinOptions, RapidProgramState>
{
    /// <summary>The name of the motion task.</summary>
    public const string MotionTask = "T_ROB1";

    private readonly Lock _gate = new();
    private readonly Lock _signalGate = new();
    private readonly Dictionary<string, RapidTask> _tasks = new(StringComparer.OrdinalIgnoreCase);
    private readonly Dictionary<string, (string Bank, int Index)> _signals = new(StringComparer.OrdinalIgnoreCase);

    /// <summary>A controller with <paramref name="options"/> (IRB 120, not real-time, by default).</summary>
    public RapidTwinController(RapidTwinOptions? options = null)
        : base(options ?? new RapidTwinOptions(), interpolates: true)
    {
        foreach ((string name, string type) in Options.Signals)
        {
            string kind = type.ToLowerInvariant();
            if (kind is not ("signaldo" or "signaldi" or "signalao" or "signalai" or "signalgo" or "signalgi"))
            {
                throw new ArgumentException($"The signal \"{name}\" has the type \"{type}\"; the twin has signaldo, signaldi, signalao, signalai, signalgo and signalgi.", nameof(options));
            }
            string bank = kind[^2..];
            _signals[name] = (bank, _signals.Count(s => s.Value.Bank == bank));
        }
        foreach (string bank in new[] { "do", "di" })
        {
            Io.AddBits(bank, Math.Max(1, _signals.Count(s => s.Value.Bank == bank)));
        }
        foreach (string bank in new[] { "ao", "ai", "go", "gi" })
        {
            Io.AddNumbers(bank, Math.Max(1, _signals.Count(s => s.Value.Bank == bank)));
        }
    }

    private int _persistentWrites;

    /// <summary>
    /// How many times persistent data an IPers order watches were written (by any task; RWS and SetDataVal count every write):
    /// IPers orders look at their data only when it moved.
    /// </summary>
    internal int PersistentWrites => Volatile.Read(ref _persistentWrites);

    /// <summary>Counts a write of persistent data (call it after the value is stored).</summary>
    internal void PersistentWritten() => Interlocked.Increment(ref _persistentWrites);

    /// <summary>The signals of the IO configuration: banks do, di, ao, ai, go, gi, in the order of the options.</summary>
    public TwinIo Io { get; } = new();

    /// <summary>The instructions and functions RAPID programs may call.</summary>
    public IReadOnlyDictionary<string, RapidBuiltin> Builtins => RapidBuiltins.All;

    /// <summary>The PERS data, shared by every task.</summary>
    internal Dictionary<string, RapidCell> Persistents { get; } = new(StringComparer.OrdinalIgnoreCase);

    /// <summary>The task called <paramref name="name"/>, made when first asked for.</summary>
    public RapidTask Task(string name = MotionTask)
    {
        lock (_gate)
        {
            if (!_tasks.TryGetValue(name, out RapidTask? task))
            {
                task = new RapidTask(this, name);
                _tasks[name] = task;
            }
            return task;
        }
    }

    /// <summary>Loads modules (name, text) into the motion task; throws <see cref="RapidLoadException"/> for the first mistake.</summary>
    public void Load(params (string Name, string Text)[] modules) => Task().Load(modules);

    /// <summary>
    /// Loads a program as the controller does: a <c>.pgf</c> file lists its modules (<c>&lt;Module&gt;name.mod&lt;/Module&gt;</c>), a
    /// <c>.mod</c> file is one module, a folder holds one <c>.pgf</c> or its <c>.mod</c> files.
    /// </summary>
    public void LoadFrom(string path) => Load([.. ModuleFiles(path).Select(f => (Path.GetFileName(f), ReadModule(f)))]);

    /// <summary>The text of module file <paramref name="file"/>, refused before it is read when it is longer than the limit allows.</summary>
    private string ReadModule(string file)
    {
        long most = Options.Limits.MaxProgramChars;
        if (new FileInfo(file).Length > most)
        {
            throw new RapidLoadException(1, RapidLoadException.Syntax($"the module file is larger than {most} bytes (the twin's limit)")) { Module = Path.GetFileName(file) };
        }
        return File.ReadAllText(file);
    }

    /// <summary>The module files of a program path (see <see cref="LoadFrom"/>).</summary>
    public static IReadOnlyList<string> ModuleFiles(string path)
    {
        if (Directory.Exists(path))
        {
            string[] programs = Directory.GetFiles(path, "*.pgf");
            if (programs.Length == 1)
            {
                return ModuleFiles(programs[0]);
            }
            // System modules (.sys) first, as the controller loads them before the program; then the program's modules.
            string[] system = Directory.GetFiles(path, "*.sys");
            string[] modules = Directory.GetFiles(path, "*.mod");
            Array.Sort(system, StringComparer.Ordinal);
            Array.Sort(modules, StringComparer.Ordinal);
            return system.Length + modules.Length > 0 ? [.. system, .. modules] : throw new FileNotFoundException($"The folder \"{path}\" has no .pgf, .mod or .sys file.");
        }
        if (path.EndsWith(".pgf", StringComparison.OrdinalIgnoreCase))
        {
            string folder = Path.GetDirectoryName(Path.GetFullPath(path))!;
            return [.. XDocument.Load(path).Descendants("Module").Select(m => Path.Combine(folder, m.Value.Trim()))];
        }
        return [path];
    }

    /// <summary>
    /// Runs <paramref name="entry"/> (main) of the motion task to its end: EXIT or the end of main finish it, Stop stops it, an error
    /// that no handler takes fails it and its message goes to the event log.
    /// </summary>
    public RapidProgramState Run(string entry = "main", CancellationToken cancellation = default)
    {
        ProgramStatus.Set(RapidProgramState.Running, null);
        RapidTask task = Task();
        RapidProgramState state = RunTask(task, entry, cancellation);
        ProgramStatus.Set(state, task.Error);
        return state;
    }

    /// <summary>The IO bank and index of signal <paramref name="name"/>, or null when the configuration has no such signal.</summary>
    internal (string Bank, int Index)? Signal(string name) => _signals.TryGetValue(name, out (string Bank, int Index) s) ? s : null;
}
