namespace Machina.Benchmarks;

/// <summary>
/// Compiles a toolpath of moves to one language, either into an in-memory program (<c>Robot.Compile</c>) or straight into
/// files (<c>Robot.CompileToFolder</c>, which must not hold the program text in memory).
/// </summary>
internal sealed class CompileScenario(Workloads workloads, RobotType language, bool toFolder) : Scenario
{
    private string? _folder;

    public override string Name => (toFolder ? "folder-" : "compile-") + language.ToString().ToLowerInvariant();

    public override string Title => toFolder ? $"Compile moves to {language} files (CompileToFolder)" : $"Compile moves to a {language} program in memory";

    public override string Unit => "move";

    public override int TargetSize => 1_000_000;

    public override Target Target { get; } = Target.Seconds(1, 1_000_000, "<= 1 s per 10^6");

    public override string? Unavailable()
    {
        var probe = Robot.Create("Probe", RobotType.ABB);
        probe.MoveTo(300, 0, 500);
        try
        {
            probe.Compile(language);
            return null;
        }
        catch (NotSupportedException ex)
        {
            return ex.Message;
        }
    }

    public override Func<object?> Prepare(int size)
    {
        Robot bot = workloads.Toolpath(size);
        if (!toFolder)
        {
            return () => bot.Compile(language);
        }
        _folder = Path.Combine(Path.GetTempPath(), $"machina-bench-{Environment.ProcessId}-{Name}");
        string folder = _folder;
        return () => bot.CompileToFolder(folder, language);
    }

    public override void Cleanup()
    {
        if (_folder is not null && Directory.Exists(_folder))
        {
            Directory.Delete(_folder, recursive: true);
        }
        _folder = null;
    }
}
