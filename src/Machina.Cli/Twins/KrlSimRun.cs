using Machina.Cli.Commands;
using Machina.Simulation.Krl;
using Machina.Simulation.Twin;

namespace Machina.Cli.Twins;

/// <summary>
/// <c>machina sim kuka --load PROGRAM</c>: a compiled KRL program on the KRL twin, in real time, with the EthernetKRL configurations
/// (.xml) and RSI files (contexts .rsix and .rsi.xml, ETHERNET object configurations .xml) of its folder, as the controller keeps them.
/// </summary>
internal static class KrlSimRun
{
    /// <summary>
    /// Loads the program (with its folder's modules, EthernetKRL configurations and RSI files) and runs it, telling each step;
    /// <paramref name="select"/> (--select) names the program the robot interpreter runs instead of the first, or "none": no
    /// program selected, as a controller stands before someone selects one (a submit program may, with CWRITE's RUN).
    /// </summary>
    internal static async Task<int> RunAsync(string path, string? select, RobotModel model, CliContext context)
    {
        List<(string Name, string Text)> files;
        try
        {
            files = [.. SelectedProgramFiles(context.FullPath(path)).Select(f => (Path.GetFileName(f), File.ReadAllText(f)))];
        }
        catch (Exception ex) when (ex is IOException or UnauthorizedAccessException)
        {
            throw new CliException($"Cannot read the KRL program \"{path}\": {ex.Message}");
        }
        using var twin = new KrlTwinController(new KrlTwinOptions { Model = model, Time = context.Time, RealTime = true });
        TextWriter output = context.Stdout;
        try
        {
            twin.Load([.. files]);
            await AddEkiConfigurationsAsync(twin, context.FullPath(path), output).ConfigureAwait(false);
        }
        catch (KrlLoadException ex)
        {
            await output.WriteLineAsync($"FAILED: {ex.Message}").ConfigureAwait(false);
            return ExitCodes.Failed;
        }
        catch (FormatException ex)
        {
            await output.WriteLineAsync($"FAILED: {ex.Message}").ConfigureAwait(false);
            return ExitCodes.Failed;
        }
        if (select is not null && !twin.Select(string.Equals(select, "none", StringComparison.OrdinalIgnoreCase) ? null : select))
        {
            await output.WriteLineAsync($"FAILED: --select {select}: no program (a routine without parameters) of that name is loaded").ConfigureAwait(false);
            return ExitCodes.Failed;
        }
        twin.EkiOpened += (name, how) => output.WriteLine($"  EthernetKRL channel {name} open: {how}");
        string loaded = string.Join(", ", files.Select(f => f.Name));
        await output.WriteLineAsync(twin.MainRoutine is { } main
            ? $"Running {main} ({loaded}) on a KRL twin of a {model} in real time. Press Ctrl+C to stop."
            : $"Loaded {loaded} on a KRL twin of a {model} in real time, no program selected ($PRO_STATE1 #P_FREE): the robot interpreter runs the program a submit program selects (CWRITE($CMD, …, \"RUN /R1/NAME()\")). Press Ctrl+C to stop.").ConfigureAwait(false);
        foreach (string line in twin.Pendant.Lines)
        {
            await output.WriteLineAsync("  pendant: " + line).ConfigureAwait(false); // what the load noted (a machine data list set aside)
        }
        twin.Pendant.Logged += line => output.WriteLine("  pendant: " + line);
        Task submit = StartSubmit(twin, files, output, context.Cancellation);
        KrlProgramState? state = null;
        int told = 0;
        if (twin.MainRoutine is not null)
        {
            state = await Task.Run(() => twin.Run(null, context.Cancellation)).ConfigureAwait(false);
            told = await TellRunAsync(twin, state.Value, told, output).ConfigureAwait(false);
        }
        if (!submit.IsCompleted)
        {
            await output.WriteLineAsync("The submit interpreter runs on until Ctrl+C.").ConfigureAwait(false);
            while (await Task.Run(() => twin.RunNextSelected(context.Cancellation)).ConfigureAwait(false) is { } next)
            {
                state = next;
                told = await TellRunAsync(twin, next, told, output).ConfigureAwait(false);
            }
            await submit.ConfigureAwait(false);
        }
        return state is null or KrlProgramState.Finished ? ExitCodes.Ok : ExitCodes.Failed;
    }

    /// <summary>Tells the steps of the run that ended (the arm's trace after the first <paramref name="told"/>) and how it ended; the steps told so far.</summary>
    private static async Task<int> TellRunAsync(KrlTwinController twin, KrlProgramState state, int told, TextWriter output)
    {
        IReadOnlyList<TwinTraceEntry> trace = twin.Arm.Trace;
        foreach (TwinTraceEntry step in trace.Skip(told))
        {
            await output.WriteLineAsync(FormattableString.Invariant(
                $"  line {step.Line,-5} {step.Seconds,9:0.000} s  {step.Text}: TCP {step.Tcp.Position}, joints {step.Joints}")).ConfigureAwait(false);
        }
        await output.WriteLineAsync(state switch
        {
            KrlProgramState.Finished => FormattableString.Invariant($"OK: the program ran to its end in {twin.Clock.Seconds:0.###} s"),
            KrlProgramState.Stopped => "STOPPED: the program was stopped before its end",
            _ => $"FAILED: {twin.Error}",
        }).ConfigureAwait(false);
        return trace.Count;
    }

    /// <summary>
    /// Runs the folder's submit program (a <c>.sub</c> file such as sps.sub, whose USER INIT and USER PLC folds call the program's
    /// routines, as KUKA's EKI server is installed) in the submit interpreter beside the robot program, until Ctrl+C; none: done.
    /// </summary>
    private static Task StartSubmit(KrlTwinController twin, List<(string Name, string Text)> files, TextWriter output, CancellationToken cancellation)
    {
        string? sub = files.Select(f => f.Name).FirstOrDefault(n => n.EndsWith(".sub", StringComparison.OrdinalIgnoreCase));
        if (sub is null || !twin.Modules.TryGetValue(Path.GetFileNameWithoutExtension(sub), out KrlModule? module) || module.Routines.Count == 0)
        {
            return Task.CompletedTask;
        }
        string routine = module.Routines[0].Name;
        output.WriteLine($"Submit interpreter: {sub} ({routine}) runs beside the robot program, one turn of its LOOP per 12 ms cycle");
        return Task.Factory.StartNew(() => twin.RunSubmit(routine, TimeSpan.FromMilliseconds(12), cancellation),
            cancellation, TaskCreationOptions.LongRunning, TaskScheduler.Default);
    }

    /// <summary>
    /// The files of <paramref name="path"/>: a folder's (its first .src is the program), or a selected .src with its .dat and then the
    /// other modules of its folder, as a controller has them on its disk beside the program (their GLOBAL routines callable), then
    /// the folder's submit programs (.sub).
    /// </summary>
    private static List<string> SelectedProgramFiles(string path)
    {
        List<string> files = [.. KrlTwinController.ProgramFiles(path)];
        string folder = Directory.Exists(path) ? path : Path.GetDirectoryName(Path.GetFullPath(path)) ?? ".";
        if (File.Exists(path))
        {
            files.AddRange(KrlTwinController.ProgramFiles(folder).Where(f => !files.Contains(f, StringComparer.OrdinalIgnoreCase)));
        }
        string[] submit = Directory.GetFiles(folder, "*.sub");
        Array.Sort(submit, StringComparer.Ordinal);
        files.AddRange(submit);
        return files;
    }

    /// <summary>Gives the twin every EthernetKRL configuration of the program's folder and names each channel in the log.</summary>
    private static async Task AddEkiConfigurationsAsync(KrlTwinController twin, string path, TextWriter output)
    {
        string folder = Directory.Exists(path) ? path : Path.GetDirectoryName(path) ?? ".";
        string[] configurations = [.. Directory.GetFiles(folder, "*.xml"), .. Directory.GetFiles(folder, "*.rsix")];
        Array.Sort(configurations, StringComparer.Ordinal);
        foreach (string file in configurations)
        {
            string text = await File.ReadAllTextAsync(file).ConfigureAwait(false);
            if (IsRsiFile(file, text))
            {
                twin.AddRsiFile(Path.GetFileName(file), text);
                await output.WriteLineAsync($"RSI file {Path.GetFileName(file)}: read when the program creates its context (RSI_CREATE)").ConfigureAwait(false);
                continue;
            }
            if (!text.Contains("<ETHERNETKRL", StringComparison.OrdinalIgnoreCase))
            {
                continue;
            }
            string name = Path.GetFileNameWithoutExtension(file);
            twin.AddEkiConfiguration(name, text);
            await output.WriteLineAsync($"EthernetKRL channel {name} ({Path.GetFileName(file)}): served when the program opens it (EKI_Open)").ConfigureAwait(false);
        }
    }

    /// <summary>An RSI context (.rsix, .rsi.xml) or an RSI ETHERNET object's configuration (ROOT with CONFIG and IP_NUMBER).</summary>
    private static bool IsRsiFile(string file, string text) =>
        file.EndsWith(".rsix", StringComparison.OrdinalIgnoreCase) || file.EndsWith(".rsi.xml", StringComparison.OrdinalIgnoreCase)
        || (text.Contains("<ROOT>", StringComparison.OrdinalIgnoreCase) && text.Contains("<IP_NUMBER>", StringComparison.OrdinalIgnoreCase));
}
