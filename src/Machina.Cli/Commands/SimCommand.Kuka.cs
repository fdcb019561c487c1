using Machina.Simulation.Krl;
using Machina.Simulation.Twin;

namespace Machina.Cli.Commands;

/// <summary><c>machina sim kuka --load PROGRAM</c>: a compiled KRL program on the KRL twin, in real time.</summary>
internal static partial class SimCommand
{
    internal static async Task<int> RunKrlAsync(string path, RobotModel model, CliContext context)
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
        twin.EkiOpened += (name, how) => output.WriteLine($"  EthernetKRL channel {name} open: {how}");
        await output.WriteLineAsync($"Running {twin.MainRoutine} ({string.Join(", ", files.Select(f => f.Name))}) on a KRL twin of a {model} in real time. Press Ctrl+C to stop.").ConfigureAwait(false);
        twin.Pendant.Logged += line => output.WriteLine("  pendant: " + line);
        KrlProgramState state = await Task.Run(() => twin.Run(null, context.Cancellation)).ConfigureAwait(false);
        foreach (TwinTraceEntry step in twin.Arm.Trace)
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
        return state == KrlProgramState.Finished ? ExitCodes.Ok : ExitCodes.Failed;
    }

    /// <summary>
    /// The files of <paramref name="path"/>: a folder's (its first .src is the program), or a selected .src with its .dat and then the
    /// other modules of its folder, as a controller has them on its disk beside the program (their GLOBAL routines callable).
    /// </summary>
    private static List<string> SelectedProgramFiles(string path)
    {
        List<string> files = [.. KrlTwinController.ProgramFiles(path)];
        if (File.Exists(path) && Path.GetDirectoryName(Path.GetFullPath(path)) is { } folder)
        {
            files.AddRange(KrlTwinController.ProgramFiles(folder).Where(f => !files.Contains(f, StringComparer.OrdinalIgnoreCase)));
        }
        return files;
    }
}
