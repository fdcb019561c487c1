namespace Machina;

/// <summary>Reads Machina instruction text (as written by <c>ToInstruction()</c> or a <c>.machina</c> program) into actions.</summary>
public static class Instructions
{
    /// <summary>
    /// All actions in <paramref name="text"/>, in order. Statements look like <c>MoveTo(400, 300, 500);</c>; several may share a
    /// line; <c>//</c> starts a comment. Throws with the line and column of the first problem.
    /// </summary>
    /// <exception cref="InstructionParseException">The text is malformed or a value is not acceptable.</exception>
    public static IReadOnlyList<RobotAction> Parse(string text)
    {
        var actions = new List<RobotAction>();
        var parser = new InstructionParser(text);
        while (parser.Next() is RobotAction action)
        {
            actions.Add(action);
        }
        return actions;
    }

    /// <summary>The actions of an instruction file (UTF-8, with or without byte order mark).</summary>
    public static IReadOnlyList<RobotAction> ParseFile(string path) => Parse(File.ReadAllText(path));

    /// <summary>Reads actions one by one, for very long programs; parsing stops at the first problem.</summary>
    /// <exception cref="ArgumentNullException"><paramref name="text"/> is null (thrown at once, not when enumerating).</exception>
    public static IEnumerable<RobotAction> Enumerate(string text)
    {
        ArgumentNullException.ThrowIfNull(text);
        return Read(text);
    }

    /// <summary>Each enumeration reads the text from its start with a parser of its own.</summary>
    private static IEnumerable<RobotAction> Read(string text)
    {
        var parser = new InstructionParser(text);
        while (parser.Next() is RobotAction action)
        {
            yield return action;
        }
    }

    /// <summary>How many warnings <c>CompileToFolder</c> keeps in its result (all are counted, and all are written as comments in the program).</summary>
    public const int MaxWarningsKept = 1000;

    /// <summary>
    /// Compiles an instruction file (a <c>.machina</c> program, UTF-8) straight into program files in <paramref name="folderPath"/>,
    /// reading it statement by statement: memory stays small and the same whatever the program's length, so files of
    /// millions of lines compile without holding their actions or their code. The files are what a robot of brand
    /// <paramref name="language"/> that issued the same instructions would write with <c>CompileToFolder</c>, byte for byte.
    /// </summary>
    /// <param name="instructionFile">Path of the instruction file.</param>
    /// <param name="language">The language to write (ABB, UR, KUKA, ZMORPH, MARLIN, HUMAN or MACHINA).</param>
    /// <param name="folderPath">Folder for the program's files (created if missing; files of the same names are replaced).</param>
    /// <param name="options">Compile options (inline targets, human comments, timestamp); the defaults when null.</param>
    /// <param name="programName">The program's name; by default the file's name without extension. It is made safe for robot languages.</param>
    /// <param name="newLine">Line ending of the files written: "\n" (default) or "\r\n".</param>
    /// <param name="model">The robot arm model (e.g. from <c>RobotModels</c>), or null: with a model every motion is checked for reach,
    /// joint limits, singularities and joint speeds, as on a robot with that model, and problems become warnings.</param>
    /// <param name="cancellationToken">Stops a long compilation; the files being written are then removed.</param>
    /// <returns>The paths written and the warnings, each with the line and column of its instruction.</returns>
    /// <exception cref="InstructionParseException">A statement is malformed, or cannot be applied in the state the statements before it
    /// leave (e.g. a relative move before any absolute one); carries the line and column. No file is written or replaced then.</exception>
    /// <exception cref="IOException">The file cannot be read or the folder cannot be written.</exception>
    public static FolderCompileResult CompileToFolder(string instructionFile, RobotType language, string folderPath, CompileOptions? options = null,
        string? programName = null, string newLine = "\n", RobotModel? model = null, CancellationToken cancellationToken = default)
    {
        ArgumentException.ThrowIfNullOrWhiteSpace(instructionFile);
        if (!File.Exists(instructionFile))
        {
            throw new FileNotFoundException($"The instruction file \"{instructionFile}\" does not exist.", instructionFile);
        }
        string name = programName ?? Path.GetFileNameWithoutExtension(instructionFile);
        return CompileFileToFolder(instructionFile, () => new StreamReader(instructionFile, System.Text.Encoding.UTF8, true, 1 << 16), language, folderPath, options, name, newLine, model, cancellationToken);
    }

    /// <summary>
    /// Compiles a file read through <paramref name="open"/>, and refuses it when it changed while it was compiled: the compilers
    /// read it more than once, and a file truncated or rewritten meanwhile would give a program made of two different texts.
    /// </summary>
    internal static FolderCompileResult CompileFileToFolder(string instructionFile, Func<TextReader> open, RobotType language, string folderPath,
        CompileOptions? options, string name, string newLine, RobotModel? model, CancellationToken cancellationToken)
    {
        var before = new FileInfo(instructionFile);
        (long length, DateTime written) = (before.Length, before.LastWriteTimeUtc);
        void Unchanged()
        {
            var after = new FileInfo(instructionFile);
            if (!after.Exists || after.Length != length || after.LastWriteTimeUtc != written)
            {
                throw new IOException($"The instruction file \"{instructionFile}\" changed while it was compiled ({length} bytes before, " +
                    $"{(after.Exists ? after.Length + " bytes" : "gone")} after); nothing was written. Compile it again once it is complete.");
            }
        }
        return CompileToFolder(open, language, folderPath, options, name, newLine, model, cancellationToken, Unchanged);
    }

    /// <summary>
    /// Compiles instruction text read from <paramref name="instructions"/> (e.g. standard input) straight into program files in
    /// <paramref name="folderPath"/>, like the file overload. The compilers read a program more than once, so the text is first copied
    /// to a temporary file (deleted afterwards) rather than kept in memory. The reader is read to its end but not closed.
    /// </summary>
    /// <param name="instructions">The instruction text.</param>
    /// <param name="language">The language to write.</param>
    /// <param name="folderPath">Folder for the program's files (created if missing; files of the same names are replaced).</param>
    /// <param name="options">Compile options; the defaults when null.</param>
    /// <param name="programName">The program's name (default "Machina"), made safe for robot languages.</param>
    /// <param name="newLine">Line ending of the files written: "\n" (default) or "\r\n".</param>
    /// <param name="model">The robot arm model, or null: with a model every motion is checked, as in the file overload.</param>
    /// <param name="cancellationToken">Stops a long compilation; the files being written are then removed.</param>
    /// <returns>The paths written and the warnings, each with the line and column of its instruction.</returns>
    /// <exception cref="InstructionParseException">A statement is malformed or cannot be applied; carries the line and column. No file is written or replaced then.</exception>
    public static FolderCompileResult CompileToFolder(TextReader instructions, RobotType language, string folderPath, CompileOptions? options = null,
        string programName = "Machina", string newLine = "\n", RobotModel? model = null, CancellationToken cancellationToken = default)
    {
        ArgumentNullException.ThrowIfNull(instructions);
        string spool = Path.GetTempFileName();
        try
        {
            using (var copy = new StreamWriter(spool, append: false, new System.Text.UTF8Encoding(false), 1 << 16))
            {
                char[] buffer = new char[1 << 14];
                int read;
                while ((read = instructions.Read(buffer, 0, buffer.Length)) > 0)
                {
                    cancellationToken.ThrowIfCancellationRequested();
                    copy.Write(buffer, 0, read);
                }
            }
            return CompileToFolder(() => new StreamReader(spool, System.Text.Encoding.UTF8, true, 1 << 16), language, folderPath, options, programName, newLine, model, cancellationToken, beforeCommit: null);
        }
        finally
        {
            File.Delete(spool);
        }
    }

    private static FolderCompileResult CompileToFolder(Func<TextReader> open, RobotType language, string folderPath, CompileOptions? options,
        string programName, string newLine, RobotModel? model, CancellationToken cancellationToken, Action? beforeCommit)
    {
        Compiler compiler = Compilers.For(EnumText.RequireDefined(language, nameof(language)));
        ArgumentException.ThrowIfNullOrWhiteSpace(folderPath);
        if (newLine is not ("\n" or "\r\n"))
        {
            throw new ArgumentException("Lines end with \"\\n\" or \"\\r\\n\".", nameof(newLine));
        }
        var source = new InstructionSource(open, cancellationToken);
        var job = new CompileJob(CompileJob.SafeProgramName(programName), source, options ?? CompileOptions.Default) { Source = source, MaxWarningsKept = MaxWarningsKept, Model = model };
        IReadOnlyList<string> paths = compiler.CompileToFolder(job, folderPath, newLine, replaceAtEnd: true, beforeCommit);
        return new FolderCompileResult(job.ProgramName, language, paths, job.Warnings, job.WarningCount, source.Count);
    }
}
