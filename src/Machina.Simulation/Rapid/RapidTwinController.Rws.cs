namespace Machina.Simulation.Rapid;

/// <summary>
/// What Robot Web Services do to the twin (see Rws/RwsTwinServer): load a module file into a task, replacing one of the same
/// name, start and stop execution again, and read or write a module's data while the program runs.
/// </summary>
internal sealed partial class RapidTwinController
{
    private readonly Dictionary<string, List<(string File, string Name, string Text)>> _loadedFiles = new(StringComparer.OrdinalIgnoreCase);

    /// <summary>
    /// True while a NORMAL task runs: the controller's execution state (a static or semistatic task runs in the background whatever
    /// it says).
    /// </summary>
    public bool IsRunning
    {
        get
        {
            RapidTask[] tasks;
            lock (_gate)
            {
                tasks = [.. _tasks.Values];
            }
            return tasks.Any(t => t.IsNormal && t.State == RapidProgramState.Running);
        }
    }

    /// <summary>The names of the tasks.</summary>
    public IReadOnlyList<string> TaskNames
    {
        get
        {
            lock (_gate)
            {
                return [.. _tasks.Keys];
            }
        }
    }

    /// <summary>
    /// Loads the module file <paramref name="file"/> into <paramref name="task"/> as the controller does (a mistake refuses it with its
    /// line); with <paramref name="replace"/>, a module of the same name loaded this way before is replaced, else refused.
    /// </summary>
    public void LoadModuleFile(string task, string file, string text, bool replace)
    {
        RapidModule parsed;
        try
        {
            parsed = RapidParser.Parse(text, Options.Limits);
        }
        catch (RapidLoadException ex)
        {
            throw new RapidLoadException(ex.Line, ex.Reason) { Module = file };
        }
        List<(string File, string Name, string Text)> loaded;
        lock (_gate)
        {
            loaded = _loadedFiles.TryGetValue(task, out var l) ? l : _loadedFiles[task] = [];
        }
        bool present = Task(task).Program.Modules.Any(m => m.Name.Equals(parsed.Name, StringComparison.OrdinalIgnoreCase));
        if (present && !replace)
        {
            throw new RapidLoadException(parsed.Line, RapidLoadException.Reference($"a module named '{parsed.Name}' is already loaded")) { Module = file };
        }
        var kept = loaded.Where(m => !m.Name.Equals(parsed.Name, StringComparison.OrdinalIgnoreCase)).ToList();
        try
        {
            if (present)
            {
                Rebuild(task, kept);
            }
            Task(task).Load([(file, text)]);
        }
        catch (RapidLoadException)
        {
            Rebuild(task, kept); // a module refused halfway leaves nothing behind
            loaded.Clear();
            loaded.AddRange(kept);
            throw;
        }
        loaded.Clear();
        loaded.AddRange(kept);
        loaded.Add((file, parsed.Name, text));
    }

    /// <summary>Starts every task's main again (after a stop or an end), as the controller's start after a program pointer reset.</summary>
    public void RestartTasks()
    {
        bool stale;
        lock (_gate)
        {
            stale = _stop is not null;
        }
        if (stale)
        {
            StopTasks(TimeSpan.FromSeconds(10));
        }
        StartTasks();
    }

    /// <summary>The global data cell <paramref name="symbol"/> declared in <paramref name="module"/> of <paramref name="task"/>, or null.</summary>
    public RapidCell? FindData(string task, string module, string symbol)
    {
        RapidTask? t;
        lock (_gate)
        {
            t = _tasks.GetValueOrDefault(task);
        }
        RapidModule? m = t?.Program.Modules.FirstOrDefault(x => x.Name.Equals(module, StringComparison.OrdinalIgnoreCase));
        if (m is null || !m.Data.Any(d => d.Name.Equals(symbol, StringComparison.OrdinalIgnoreCase) && !d.Local))
        {
            return null;
        }
        return t!.Program.Globals.GetValueOrDefault(symbol);
    }

    private void Rebuild(string task, List<(string File, string Name, string Text)> modules)
    {
        lock (_gate)
        {
            // A new program in the same task: its Type is the configuration's, not the program's.
            RapidTaskType type = _tasks.TryGetValue(task, out RapidTask? old) ? old.Type : RapidTaskType.Normal;
            _tasks[task] = new RapidTask(this, task) { Type = type };
        }
        if (modules.Count > 0)
        {
            Task(task).Load(modules.Select(m => (m.File, m.Text)));
        }
    }
}
