namespace Machina.Benchmarks;

/// <summary>
/// Compiles an instruction file to a folder with the streaming entry point <c>Instructions.CompileToFolder</c> (warm, in this
/// process); the whole-process scenarios (--process) time the same work in a fresh process.
/// </summary>
internal sealed class FileCompileScenario(RobotType language) : Scenario
{
    private readonly ProcessInputs _inputs = new();

    public override string Name => "file-" + language.ToString().ToLowerInvariant();

    public override string Title => $"Compile an instruction file to {language} files (Instructions.CompileToFolder)";

    public override string Unit => "line";

    public override int TargetSize => 1_000_000;

    public override Target Target { get; } = Target.Seconds(1, 1_000_000, "<= 1 s per 10^6");

    public override Func<object?> Prepare(int size)
    {
        string file = _inputs.InstructionFile(size);
        string folder = _inputs.Folder(Name);
        return () => Instructions.CompileToFolder(file, language, folder);
    }

    public override void Cleanup() => _inputs.Dispose();
}
