using Machina.Simulation.Rapid;

namespace Machina.Cli.Commands;

/// <summary><c>machina sim abb --load PROGRAM</c>: a virtual ABB that loads a compiled RAPID program and runs its <c>main</c> in real time.</summary>
internal static class SimLoad
{
    /// <summary>Loads <paramref name="path"/> (.mod, .pgf or folder) into T_ROB1 and runs main until it ends or Ctrl+C, telling the pendant's lines.</summary>
    internal static async Task<int> RunAbbAsync(string path, RobotModel? model, CliContext context)
    {
        var options = new RapidTwinOptions
        {
            Model = model ?? Brands.Model(AbbBrand.Definition.DefaultModel, AbbBrand.Definition.Type)!,
            RealTime = true,
            Time = context.Time,
        };
        var twin = new RapidTwinController(options);
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
        try
        {
            twin.LoadFrom(context.FullPath(path));
        }
        catch (RapidLoadException ex)
        {
            Log($"FAILED: {ex.Module}: {ex.Message}");
            return ExitCodes.Failed;
        }
        catch (Exception ex) when (ex is IOException or UnauthorizedAccessException or System.Xml.XmlException)
        {
            throw new CliException($"Cannot read the RAPID program \"{path}\": {ex.Message}");
        }
        twin.Pendant.Logged += line => Log("  pendant: " + line);
        Log($"Running {path} on a virtual {options.Model} (RAPID, task T_ROB1) in real time. Press Ctrl+C to stop.");
        RapidProgramState state = await Task.Run(() => twin.Run("main", context.Cancellation)).ConfigureAwait(false);
        Log(state switch
        {
            RapidProgramState.Finished => FormattableString.Invariant($"The program ended after {twin.Clock.Seconds:0.###} s of program time."),
            RapidProgramState.Failed => $"FAILED: {twin.Error}",
            _ => "Stopped.",
        });
        return state == RapidProgramState.Failed ? ExitCodes.Failed : ExitCodes.Ok;
    }
}
