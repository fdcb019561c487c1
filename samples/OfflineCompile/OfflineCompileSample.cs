// Writes the paper's "Hello Robot" program in every language Machina compiles to. No robot and no network needed.
// Usage: dotnet run --project samples/OfflineCompile [outputFolder]   (default: MachinaPrograms in the temporary folder)
namespace Machina.Samples;

/// <summary>The offline compile sample (the test suite runs it through <see cref="RunAsync"/>).</summary>
public static class OfflineCompileSample
{
    /// <summary>Runs the sample: 0 when every language was written, 2 for wrong arguments.</summary>
    public static Task<int> RunAsync(string[] args, TextWriter output, TextWriter error, CancellationToken cancellationToken)
    {
        if (args.Length > 1 || args.Length == 1 && args[0].StartsWith('-'))
        {
            error.WriteLine("Usage: OfflineCompile [outputFolder]");
            return Task.FromResult(SampleHost.Usage);
        }
        string folder = args.Length > 0 ? args[0] : Path.Combine(Path.GetTempPath(), "MachinaPrograms");

        var bot = Robot.Create("HelloRobot", RobotType.ABB);
        bot.Message("Hello Robot!");
        bot.SpeedTo(100);
        bot.MoveTo(400, 300, 500);
        bot.Rotate(0, 1, 0, -90);
        bot.Move(0, 0, 250);
        bot.Wait(2000);
        bot.AxesTo(0, 0, 0, 0, 90, 0);

        foreach (RobotType language in Enum.GetValues<RobotType>())
        {
            cancellationToken.ThrowIfCancellationRequested();
            RobotProgram program;
            try
            {
                program = bot.Compile(language);
            }
            catch (NotSupportedException ex)
            {
                output.WriteLine($"{language}: {ex.Message}");
                continue;
            }
            string target = Path.Combine(folder, language.ToString());
            foreach (string path in program.SaveToFolder(target))
            {
                output.WriteLine($"{language}: wrote {path}");
            }
            foreach (ProgramWarning warning in program.Warnings)
            {
                output.WriteLine($"{language}: warning {warning}");
            }
        }
        return Task.FromResult(SampleHost.Ok);
    }
}
