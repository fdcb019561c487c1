using Machina.Cli.Commands;
using Machina.Cli.Simulation;
using Machina.Simulation.Rapid;
using Machina.Simulation.Rws;

namespace Machina.Cli.Twins;

/// <summary>
/// <c>machina sim abb --load [TASK=]PROGRAM …</c>: a virtual ABB that loads RAPID programs into their tasks (T_ROB1 when no task is
/// named) and runs every task's <c>main</c> in real time, as a controller with the Multitasking option does.
/// </summary>
internal static class SimLoad
{
    /// <summary>One task to load: its name and the program path (.mod, .sys, .pgf or folder).</summary>
    internal readonly record struct TaskLoad(string Task, string Path);

    /// <summary>Reads <c>TASK=PATH</c> (a RAPID name before '=') or a bare PATH (the motion task T_ROB1).</summary>
    internal static TaskLoad Parse(string value)
    {
        int eq = value.IndexOf('=', StringComparison.Ordinal);
        if (eq > 0 && value[..eq].All(c => char.IsAsciiLetterOrDigit(c) || c == '_') && char.IsAsciiLetter(value[0]))
        {
            return new TaskLoad(value[..eq], value[(eq + 1)..]);
        }
        return new TaskLoad(RapidTwinController.MotionTask, value);
    }

    /// <summary>
    /// What else a --load run may have: signals of the IO configuration (<c>[TYPE:]NAME[=VALUE]</c>), RWS on a port, and the folder
    /// that is HOME: (null: a new temporary one).
    /// </summary>
    internal sealed record Extras(IReadOnlyList<string> Signals, string? Eio, System.Net.IPAddress Bind, int? RwsPort, string? Home = null)
    {
        /// <summary>The <c>--task-type TASK=TYPE</c> values: each task's Type in the system parameters (NORMAL when not given).</summary>
        public IReadOnlyList<string> TaskTypes { get; init; } = [];

        /// <summary>The <c>--cycle</c> value: the normal tasks' run mode (once when not given).</summary>
        public string? Cycle { get; init; }
    }

    /// <summary>One <c>--task-type TASK=NORMAL|STATIC|SEMISTATIC</c>.</summary>
    internal static (string Task, RapidTaskType Type) ParseTaskType(string text)
    {
        int eq = text.IndexOf('=', StringComparison.Ordinal);
        RapidTaskType? type = eq <= 0 ? null : text[(eq + 1)..].ToUpperInvariant() switch
        {
            "NORMAL" => RapidTaskType.Normal,
            "STATIC" => RapidTaskType.Static,
            "SEMISTATIC" => RapidTaskType.SemiStatic,
            _ => null,
        };
        return type is { } t ? (text[..eq], t) : throw new UsageException($"--task-type needs TASK=NORMAL, TASK=STATIC or TASK=SEMISTATIC, e.g. TASK2=SEMISTATIC, not \"{text}\".");
    }

    /// <summary>The <c>--cycle</c> value: once (single cycle, the default) or forever (continuous).</summary>
    internal static RapidExecutionCycle ParseCycle(string? text) => text switch
    {
        null or "once" => RapidExecutionCycle.Once,
        "forever" => RapidExecutionCycle.Forever,
        _ => throw new UsageException($"--cycle needs once or forever, not \"{text}\"."),
    };

    /// <summary>One <c>--signal [TYPE:]NAME[=VALUE]</c>: the RAPID type (null: a signal of the board) and the value at the start.</summary>
    internal static (string? Type, string Name, double Value) ParseSignal(string text)
    {
        string? type = null;
        int colon = text.IndexOf(':', StringComparison.Ordinal);
        if (colon > 0)
        {
            type = text[..colon].ToLowerInvariant() switch
            {
                "di" => "signaldi", "do" => "signaldo", "ai" => "signalai", "ao" => "signalao",
                _ => throw new UsageException($"--signal {text}: the type \"{text[..colon]}\" is not di, do, ai or ao."),
            };
            text = text[(colon + 1)..];
        }
        int eq = text.IndexOf('=', StringComparison.Ordinal);
        string name = eq < 0 ? text : text[..eq];
        double value = 0;
        if (name.Length == 0 || !char.IsAsciiLetter(name[0]) || !name.All(c => char.IsAsciiLetterOrDigit(c) || c == '_')
            || (eq >= 0 && !double.TryParse(text[(eq + 1)..], System.Globalization.NumberStyles.Float, System.Globalization.CultureInfo.InvariantCulture, out value)))
        {
            throw new UsageException($"--signal needs [TYPE:]NAME[=VALUE], e.g. di:signalRobotEStop=0 or DI_1=1, not \"{text}\".");
        }
        return (type, name, value);
    }

    /// <summary>The signals of the EIO.cfg file at <paramref name="path"/> (none when null), with their default values.</summary>
    private static IEnumerable<(string? Type, string Name, double Value)> Eio(string? path, CliContext context)
    {
        if (path is null)
        {
            return [];
        }
        try
        {
            return RapidEioConfig.Signals(File.ReadAllText(context.FullPath(path))).Select(s => ((string?)s.Type, s.Name, s.Default));
        }
        catch (Exception ex) when (ex is IOException or UnauthorizedAccessException)
        {
            throw new CliException($"Cannot read the IO configuration \"{path}\": {ex.Message}");
        }
    }

    /// <summary>
    /// Loads every task's program and runs every task's main until all end or Ctrl+C, telling the pendant's lines (labelled with their
    /// task when there are several tasks). With one program in T_ROB1 it tells what it always told.
    /// </summary>
    internal static async Task<int> RunAbbAsync(IReadOnlyList<string> loads, RobotModel? model, CliContext context, Extras? extras = null)
    {
        extras ??= new Extras([], null, System.Net.IPAddress.Loopback, null);
        IReadOnlyList<(string Name, string Type)> board = Machina.Simulation.VirtualAbbController.Signals;
        (string? Type, string Name, double Value)[] signals = [.. Eio(extras.Eio, context), .. extras.Signals.Select(ParseSignal)];
        foreach ((string? type, string name, _) in signals)
        {
            if (type is null && !board.Any(b => b.Name.Equals(name, StringComparison.OrdinalIgnoreCase))
                && !signals.Any(s => s.Type is not null && s.Name.Equals(name, StringComparison.OrdinalIgnoreCase)))
            {
                throw new UsageException($"--signal {name}: the board has no such signal; give its type, e.g. --signal di:{name}=0.");
            }
        }
        TaskLoad[] tasks = [.. loads.Select(Parse)];
        (string Task, RapidTaskType Type)[] types = [.. extras.TaskTypes.Select(ParseTaskType)];
        RapidExecutionCycle cycle = ParseCycle(extras.Cycle);
        foreach ((string task, _) in types.Where(t => !tasks.Any(l => l.Task.Equals(t.Task, StringComparison.OrdinalIgnoreCase))))
        {
            throw new UsageException($"--task-type {task}: no --load puts a program into the task {task}.");
        }
        foreach (IGrouping<string, TaskLoad> twice in tasks.GroupBy(t => t.Task, StringComparer.OrdinalIgnoreCase).Where(g => g.Count() > 1))
        {
            throw new UsageException($"The task {twice.Key} is loaded twice: give each task one program (a .pgf or a folder holds several modules).");
        }
        var options = new RapidTwinOptions
        {
            Model = model ?? Brands.Model(AbbBrand.Definition.DefaultModel, AbbBrand.Definition.Type)!,
            RealTime = true,
            Time = context.Time,
            HomeDirectory = extras.Home,
            // The virtual ABB's IO board (DO_1…DO_16, DI_1…DI_16, AO_1…AO_4, AI_1…AI_4) and the signals --signal declares.
            Signals = [.. board, .. signals.Where(s => s.Type is not null && !board.Any(b => b.Name.Equals(s.Name, StringComparison.OrdinalIgnoreCase)))
                .DistinctBy(s => s.Name, StringComparer.OrdinalIgnoreCase).Select(s => (s.Name, s.Type!))],
        };
        var twin = new RapidTwinController(options) { LabelsTasks = tasks.Length > 1 || tasks[0].Task != RapidTwinController.MotionTask, Cycle = cycle };
        TextWriter output = context.Stdout;
        var gate = new Lock();
        void Log(string line)
        {
            lock (gate)
            {
                output.WriteLine(line);
                output.Flush();
            }
        }
        // The motion task first, as the controller's configuration lists it; the others in the order given.
        foreach (TaskLoad load in tasks.OrderBy(t => t.Task.Equals(RapidTwinController.MotionTask, StringComparison.OrdinalIgnoreCase) ? 0 : 1))
        {
            try
            {
                twin.Task(load.Task).Load([.. RapidTwinController.ModuleFiles(context.FullPath(load.Path)).Select(f => (Path.GetFileName(f), File.ReadAllText(f)))]);
            }
            catch (RapidLoadException ex)
            {
                Log($"FAILED: {(twin.LabelsTasks ? load.Task + ": " : "")}{ex.Module}: {ex.Message}");
                return ExitCodes.Failed;
            }
            catch (Exception ex) when (ex is IOException or UnauthorizedAccessException or System.Xml.XmlException)
            {
                throw new CliException($"Cannot read the RAPID program \"{load.Path}\": {ex.Message}");
            }
        }
        foreach ((_, string name, double value) in signals)
        {
            twin.SetSignal(name, value);
        }
        foreach ((string task, RapidTaskType type) in types)
        {
            twin.Task(task).Type = type;
        }
        twin.Pendant.Logged += line => Log("  pendant: " + line);
        string names = string.Join(", ", twin.TaskNames);
        Log(tasks.Length == 1 && !twin.LabelsTasks
            ? $"Running {tasks[0].Path} on a virtual {options.Model} (RAPID, task T_ROB1) in real time. Press Ctrl+C to stop."
            : $"Running {tasks.Length} RAPID tasks ({names}) on a virtual {options.Model} in real time. Press Ctrl+C to stop.");
        if (extras.Home is not null && extras.RwsPort is null)
        {
            Log($"RAPID's HOME: is the folder {twin.HomeDirectory}.");
        }
        var ended = new TaskCompletionSource(TaskCreationOptions.RunContinuationsAsynchronously);
        int running = tasks.Length;
        twin.TaskEnded += _ =>
        {
            if (Interlocked.Decrement(ref running) == 0)
            {
                ended.TrySetResult();
            }
        };
        await using IAsyncDisposable? rws = extras.RwsPort is { } rwsPort
            ? SimWebServices.Relay(AbbBrand.Definition.Type, RwsWebServices.Serve(twin), extras.Bind, rwsPort, SimCommand.DefaultPort + 100, Log, Log) : null;
        twin.StartTasks();
        try
        {
            await ended.Task.WaitAsync(context.Cancellation).ConfigureAwait(false);
        }
        catch (OperationCanceledException)
        {
        }
        twin.StopTasks(TimeSpan.FromSeconds(10));
        bool failed = false;
        foreach (string name in twin.TaskNames)
        {
            RapidTask task = twin.Task(name);
            string label = twin.LabelsTasks ? $"{name}: " : "";
            failed |= task.State == RapidProgramState.Failed;
            Log(task.State switch
            {
                RapidProgramState.Finished when !twin.LabelsTasks => FormattableString.Invariant($"The program ended after {twin.Clock.Seconds:0.###} s of program time."),
                RapidProgramState.Finished => $"{label}the program ended.",
                RapidProgramState.Failed => $"FAILED: {label}{task.Error}",
                _ => $"{label}stopped.",
            });
        }
        return failed ? ExitCodes.Failed : ExitCodes.Ok;
    }
}
