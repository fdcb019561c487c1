using Machina.Cli.Programs;

namespace Machina.Cli.Commands;

/// <summary><c>machina compile</c>: a program of Machina instructions to a brand's files in a folder.</summary>
internal static class CompileCommand
{
    internal static readonly CliCommand Command = new(
        "compile",
        "Compile a program of Machina instructions for a robot brand",
        $"""
        Usage: machina compile PROGRAM --brand {Brands.Choices(Brands.All)} [options]

        Reads PROGRAM, a text file of Machina instructions (one per line, e.g. MoveTo(400, 300, 500);), checks every
        instruction and writes the program in the brand's language into a folder. Use - as PROGRAM to read standard input.
        Prints the paths of the files written. Warnings go to standard error as FILE:LINE:COLUMN: warning: ...

        Options:
          --brand B       the language to write: abb (RAPID .mod), ur (URScript .script), kuka (KRL .src/.dat),
                          zmorph or marlin (G-code .gcode), human (a readable listing .txt), machina (instructions .machina)
          --out DIR       the folder to write into (created if needed; default: the current folder)
          --model M       the robot arm model, e.g. "IRB 120" or UR5e (see machina models): every motion is checked for
                          reach, joint limits, singularities and joint speeds, and problems are reported as warnings
          --name NAME     the program name (default: the file name without extension)
          --no-comments   leave out the comment describing each action

        Example:
          machina compile square.machina --brand abb --out build
        Exit code: 0 when written, 1 when an instruction is malformed or cannot be applied (FILE:LINE:COLUMN: error: ...),
        2 for a mistake on the command line.
        """,
        Options: ["--brand", "--out", "--model", "--name"],
        Flags: ["--no-comments"],
        RunAsync);

    private static async Task<int> RunAsync(CliArgs args, CliContext context)
    {
        string path = args.Single("a PROGRAM file (or - for standard input)");
        RobotType brand = Brands.Parse(args.Required("--brand", "(one of " + string.Join(", ", Brands.All.Select(Brands.Name)) + ")"), Brands.All);
        RobotModel? model = Brands.Model(args.Value("--model"), brand);
        string folder = context.FullPath(args.Value("--out") ?? ".");
        var options = new CompileOptions { HumanComments = !args.Has("--no-comments") };
        using ProgramReader reader = ProgramReader.Open(path, context, args.Value("--name"));
        CompileResult result = await CompileStreamAsync(reader, brand, model, options, folder, context).ConfigureAwait(false);
        foreach (string written in result.Paths)
        {
            await context.Stdout.WriteLineAsync(Display(written, context)).ConfigureAwait(false);
        }
        await context.Stderr.WriteLineAsync(
            $"Compiled {result.Actions} action{(result.Actions == 1 ? "" : "s")} of {reader.DisplayName} for {brand}" +
            (model is null ? "" : $" ({model})") + $": {result.Paths.Count} file{(result.Paths.Count == 1 ? "" : "s")}, " +
            $"{result.Warnings} warning{(result.Warnings == 1 ? "" : "s")}.").ConfigureAwait(false);
        return ExitCodes.Ok;
    }

    /// <summary>What a compile wrote.</summary>
    internal sealed record CompileResult(IReadOnlyList<string> Paths, int Actions, int Warnings);

    /// <summary>
    /// THE compile of the command line, in one place: the library's streaming compile (<c>Instructions.CompileToFolder</c>) reads the
    /// program statement by statement, applies and checks each, and writes the brand's files into <paramref name="folder"/>, so memory
    /// does not grow with the program. Errors and warnings are reported with their line and column; of the warnings, the library keeps
    /// the first <see cref="Instructions.MaxWarningsKept"/> (all are counted, and all are comments in the program).
    /// </summary>
    /// <exception cref="CliException">An instruction is malformed or cannot be applied (located), or the folder cannot be written.</exception>
    internal static Task<CompileResult> CompileStreamAsync(ProgramReader reader, RobotType brand, RobotModel? model, CompileOptions options, string folder, CliContext context)
    {
        FolderCompileResult result;
        try
        {
            result = reader.FilePath is string file
                ? Instructions.CompileToFolder(file, brand, folder, options, reader.ProgramName, model: model, cancellationToken: context.Cancellation)
                : Instructions.CompileToFolder(reader.Input, brand, folder, options, reader.ProgramName, model: model, cancellationToken: context.Cancellation);
        }
        catch (InstructionParseException ex)
        {
            throw CliException.At(reader.DisplayName, ex.Line, ex.Column, ex.Problem);
        }
        catch (Exception ex) when (ex is IOException or UnauthorizedAccessException)
        {
            throw new CliException($"Cannot compile \"{reader.DisplayName}\" into \"{folder}\": {ex.Message}");
        }
        foreach (ProgramWarning warning in result.Warnings)
        {
            context.Stderr.WriteLine($"{reader.DisplayName}:{warning.Line ?? 0}:{warning.Column ?? 0}: warning: {warning.Instruction} {warning.Message}");
        }
        if (result.WarningCount > result.Warnings.Count)
        {
            int more = result.WarningCount - result.Warnings.Count;
            context.Stderr.WriteLine($"{reader.DisplayName}: and {more} more warning{(more == 1 ? "" : "s")} (the program notes each as a comment; a run of the same warning shares one).");
        }
        return Task.FromResult(new CompileResult(result.Paths, result.ActionCount, result.WarningCount));
    }

    /// <summary>A path relative to the working folder when it is inside it, else the full path.</summary>
    internal static string Display(string path, CliContext context)
    {
        string relative = Path.GetRelativePath(context.WorkingDirectory, path);
        return relative.StartsWith("..", StringComparison.Ordinal) || Path.IsPathRooted(relative) ? path : relative;
    }
}
