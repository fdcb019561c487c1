namespace Machina;

/// <summary>
/// Turns a list of issued actions into a program in one device language. A compiler is a fold: it replays the actions on
/// a fresh cursor and writes code from the state after each action, so relative actions become absolute targets.
/// </summary>
internal abstract class Compiler
{
    /// <summary>The language this compiler writes.</summary>
    internal abstract RobotType Brand { get; }

    /// <summary>What starts a comment in this language.</summary>
    internal abstract string CommentPrefix { get; }

    /// <summary>
    /// Writes the program's files into <paramref name="output"/>, opening each file with <c>output.OpenFile</c> and adding its
    /// lines in order. Never throws for actions the device cannot express: they become comments and warnings (<c>job.Warn</c>).
    /// </summary>
    internal abstract void Emit(CompileJob job, ProgramOutput output);

    /// <summary>Compiles the job into an in-memory program.</summary>
    internal RobotProgram Compile(CompileJob job)
    {
        using var output = new MemoryProgramOutput();
        Emit(job, output);
        return output.ToProgram(job.ProgramName, Brand, job.Warnings);
    }

    /// <summary>
    /// Compiles the job straight into files in <paramref name="folder"/>; returns their paths. <paramref name="beforeCommit"/>
    /// runs after the last line is written and before the files take their names; when it throws, no file remains.
    /// </summary>
    internal IReadOnlyList<string> CompileToFolder(CompileJob job, string folder, string newLine = "\n", bool replaceAtEnd = false, Action? beforeCommit = null)
    {
        using var output = new FolderProgramOutput(folder, newLine, replaceAtEnd);
        Emit(job, output);
        beforeCommit?.Invoke();
        output.Commit();
        return output.Paths;
    }

    /// <summary>Our short header: program name, library version, a safety notice, and the date only when asked.</summary>
    internal IEnumerable<string> Header(CompileJob job)
    {
        string cc = CommentPrefix;
        yield return $"{cc} Program \"{job.ProgramName}\" written by {LibraryInfo.NameAndVersion} for {Brand}.";
        if (job.Options.Timestamp is DateTimeOffset when)
        {
            yield return $"{cc} Created {when.ToString("yyyy-MM-dd HH:mm:ss zzz", Num.Inv)}.";
        }
        yield return $"{cc} Safety: this program moves a machine that can hurt people. Check it in simulation first,";
        yield return $"{cc} run it at reduced speed, keep clear of the working area and keep the emergency stop in reach.";
    }
}
