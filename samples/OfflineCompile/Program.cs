// Writes the paper's "Hello Robot" program in every language Machina compiles to.
// Usage: dotnet run --project samples/OfflineCompile [outputFolder]
using Machina;

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
    RobotProgram program;
    try
    {
        program = bot.Compile(language);
    }
    catch (NotSupportedException ex)
    {
        Console.WriteLine($"{language}: {ex.Message}");
        continue;
    }
    string target = Path.Combine(folder, language.ToString());
    foreach (string path in program.SaveToFolder(target))
    {
        Console.WriteLine($"{language}: wrote {path}");
    }
    foreach (ProgramWarning warning in program.Warnings)
    {
        Console.WriteLine($"{language}: warning {warning}");
    }
}
