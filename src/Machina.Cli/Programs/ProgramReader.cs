namespace Machina.Cli.Programs;

/// <summary>
/// A program of Machina instructions from a file or standard input, read as it goes by the library's own reader
/// (<see cref="InstructionStatement.ReadAll"/>), so that a program of any length is read in constant memory. Each action comes
/// with the line and column where its statement starts; a malformed statement ends the reading with <c>file:line:column: error: …</c>.
/// </summary>
internal sealed class ProgramReader : IDisposable
{
    private readonly TextReader _reader;
    private readonly bool _ownsReader;

    private ProgramReader(TextReader reader, bool ownsReader, string displayName, string programName, string? filePath = null)
    {
        FilePath = filePath;
        _reader = reader;
        _ownsReader = ownsReader;
        DisplayName = displayName;
        ProgramName = programName;
    }

    /// <summary>The program as named in messages: its path as given, or "&lt;stdin&gt;".</summary>
    internal string DisplayName { get; }

    /// <summary>The name compiled programs get: the name given to <see cref="Open"/>, else the file name without extension.</summary>
    internal string ProgramName { get; }

    /// <summary>The full path of the program file, or null for standard input.</summary>
    internal string? FilePath { get; }

    /// <summary>The text being read (the file, or standard input), for a reader of its own such as the library's compile.</summary>
    internal TextReader Input => _reader;

    /// <summary>True when the program comes from standard input.</summary>
    internal bool IsStdin => !_ownsReader;

    /// <summary>
    /// Opens <paramref name="path"/> ("-" for standard input). The program name is <paramref name="name"/> when given, else the
    /// file name without extension ("Machina" for standard input), made safe for robot languages.
    /// </summary>
    internal static ProgramReader Open(string path, CliContext context, string? name)
    {
        if (path == "-")
        {
            return new ProgramReader(context.Stdin, false, "<stdin>", CompileJob.SafeProgramName(name ?? "Machina"));
        }
        string full = context.FullPath(path);
        if (Directory.Exists(full))
        {
            throw new CliException($"\"{path}\" is a folder; give the program file (a text file of Machina instructions such as MoveTo(400, 300, 500);).");
        }
        if (!File.Exists(full))
        {
            throw new CliException($"There is no file \"{path}\" (looked in {Path.GetDirectoryName(full)}).");
        }
        StreamReader reader;
        try
        {
            reader = new StreamReader(full, System.Text.Encoding.UTF8, detectEncodingFromByteOrderMarks: true, new FileStreamOptions { BufferSize = 1 << 16 });
        }
        catch (Exception ex) when (ex is IOException or UnauthorizedAccessException)
        {
            throw new CliException($"Cannot read \"{path}\": {ex.Message}");
        }
        return new ProgramReader(reader, true, path, CompileJob.SafeProgramName(name ?? Path.GetFileNameWithoutExtension(full)), full);
    }

    /// <summary>The statements, in order, read by the library's reader as they are enumerated (in constant memory).</summary>
    /// <exception cref="CliException">A statement is malformed (the message is <c>file:line:column: error: …</c>) or the file cannot be read.</exception>
    internal IEnumerable<InstructionStatement> Read(CancellationToken cancellationToken)
    {
        using IEnumerator<InstructionStatement> statements = InstructionStatement.ReadAll(_reader, cancellationToken).GetEnumerator();
        while (true)
        {
            try
            {
                if (!statements.MoveNext())
                {
                    yield break;
                }
            }
            catch (InstructionParseException ex)
            {
                throw CliException.At(DisplayName, ex.Line, ex.Column, ex.Problem);
            }
            catch (Exception ex) when (ex is IOException or UnauthorizedAccessException)
            {
                throw new CliException($"Cannot read \"{DisplayName}\": {ex.Message}");
            }
            yield return statements.Current;
        }
    }

    /// <summary>Closes the file (standard input is left open).</summary>
    public void Dispose()
    {
        if (_ownsReader)
        {
            _reader.Dispose();
        }
    }
}
