using Machina.Simulation.Rapid;

namespace Machina.Cli.Commands;

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
    /// Loads every task's program and runs every task's main until all end or Ctrl+C, telling the pendant's lines (labelled with their
    /// task when there are several tasks). With one program in T_ROB1 it tells what it always told.
    /// </summary>
    internal static async Task<int> RunAbbAsync(IReadOnlyList<string> loads, RobotModel? model, CliContext context)
    {
        TaskLoad[] tasks = [.. loads.Select(Parse)];
        foreach (IGrouping<string, TaskLoad> twice in tasks.GroupBy(t => t.Task, StringComparer.OrdinalIgnoreCase).Where(g => g.Count() > 1))
        {
            throw new UsageException($"The task {twice.Key} is loaded twice: give each task one program (a .pgf or a folder holds several modules).");
        }
        var options = new RapidTwinOptions
        {
            Model = model ?? Brands.Model(AbbBrand.Definition.DefaultModel, AbbBrand.Definition.Type)!,
            RealTime = true,
            Time = context.Time,
            Signals = Machina.Simulation.VirtualAbbController.Signals, // the virtual ABB's IO board: DO_1…DO_16, DI_1…DI_16, AO_1…AO_4, AI_1…AI_4
        };
        var twin = new RapidTwinController(options) { LabelsTasks = tasks.Length > 1 || tasks[0].Task != RapidTwinController.MotionTask };
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
        twin.Pendant.Logged += line => Log("  pendant: " + line);
        string names = string.Join(", ", twin.TaskNames);
        Log(tasks.Length == 1 && !twin.LabelsTasks
            ? $"Running {tasks[0].Path} on a virtual {options.Model} (RAPID, task T_ROB1) in real time. Press Ctrl+C to stop."
            : $"Running {tasks.Length} RAPID tasks ({names}) on a virtual {options.Model} in real time. Press Ctrl+C to stop.");
        var ended = new TaskCompletionSource(TaskCreationOptions.RunContinuationsAsynchronously);
        int running = tasks.Length;
        twin.TaskEnded += _ =>
        {
            if (Interlocked.Decrement(ref running) == 0)
            {
                ended.TrySetResult();
            }
        };
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
