using Machina.Cli;

namespace Machina.Benchmarks;

/// <summary>
/// <c>machina compile PROGRAM --brand abb --out DIR</c> run in-process on a generated instruction file: reading, checking and writing
/// the folder. Its peak memory shows whether the command line streams (flat) or holds the program (grows with the lines).
/// </summary>
internal sealed class CliCompileScenario : Scenario
{
    private string? _folder;

    public override string Name => "cli-compile";
    public override string Title => "machina compile FILE --brand abb --out DIR";
    public override string Unit => "line";
    public override int TargetSize => 10_000_000;
    public override IReadOnlyList<int> ScalingSizes => [10_000, 100_000, 1_000_000];

    /// <summary>Informative: the throughput the command line should keep; its memory is the point (see the peak column).</summary>
    public override Target Target { get; } = Target.Seconds(10, 1_000_000, "<= 10 s per 10^6 lines");

    public override Func<object?> Prepare(int size)
    {
        Cleanup();
        _folder = Directory.CreateTempSubdirectory("machina-cli-bench-").FullName;
        string program = Path.Combine(_folder, "toolpath.machina");
        Workloads.WriteInstructionFile(program, size);
        string output = Path.Combine(_folder, "out");
        return () =>
        {
            var context = new CliContext(TextReader.Null, TextWriter.Null, TextWriter.Null, CancellationToken.None, workingDirectory: _folder);
            int exit = CliApp.RunAsync(["compile", program, "--brand", "abb", "--out", output], context).GetAwaiter().GetResult();
            return exit == ExitCodes.Ok ? exit : throw new InvalidOperationException($"machina compile ended with exit code {exit}.");
        };
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
