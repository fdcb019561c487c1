namespace Machina.Cli.Programs;

/// <summary>
/// Reads a program of Machina instructions from a file or standard input as it goes, a block of lines at a time, so that a
/// program of any length is read in constant memory. Each action comes with the line and column where its statement starts; a
/// malformed statement ends the reading with <c>file:line:column: error: …</c>. A statement may span several lines.
/// </summary>
internal sealed class ProgramReader : IDisposable
{
    /// <summary>Lines parsed at once (larger blocks cost fewer parser objects; smaller ones keep memory flat).</summary>
    internal const int BlockLines = 256;

    /// <summary>Longest statement, in lines, before an unclosed one is reported instead of read further.</summary>
    internal const int MaxStatementLines = 10_000;

    private readonly TextReader _reader;
    private readonly bool _ownsReader;
    private readonly List<string> _lines = [];
    private int _lineNumber;

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

    /// <summary>The actions, in order, read as they are enumerated.</summary>
    /// <exception cref="CliException">A statement is malformed (the message is <c>file:line:column: error: …</c>) or the file cannot be read.</exception>
    internal IEnumerable<ProgramStatement> Read(CancellationToken cancellationToken)
    {
        while (true)
        {
            cancellationToken.ThrowIfCancellationRequested();
            int blockStart = _lineNumber + 1;
            _lines.Clear();
            bool end = !ReadLines(BlockLines);
            if (_lines.Count == 0)
            {
                yield break;
            }
            string text = string.Join('\n', _lines);
            IReadOnlyList<RobotAction> actions;
            while (true)
            {
                try
                {
                    actions = Instructions.Parse(text);
                    break;
                }
                catch (InstructionParseException ex) when (!end && AtEnd(ex) && _lines.Count < BlockLines + MaxStatementLines)
                {
                    // The last statement continues on the next line: read one more and parse the block again.
                    int before = _lines.Count;
                    end = !ReadLines(1);
                    if (_lines.Count > before)
                    {
                        text = text + "\n" + _lines[^1];
                    }
                }
                catch (InstructionParseException ex)
                {
                    throw CliException.At(DisplayName, blockStart + ex.Line - 1, ex.Column, ex.Problem);
                }
            }
            List<(int Line, int Column)> starts = StatementStarts(text);
            for (int i = 0; i < actions.Count; i++)
            {
                (int line, int column) = starts.Count == actions.Count ? starts[i] : (0, 1);
                yield return new ProgramStatement(actions[i], blockStart + line, column);
            }
            if (end)
            {
                yield break;
            }
        }
    }

    /// <summary>Reads up to <paramref name="count"/> lines into the block; false at the end of the input.</summary>
    private bool ReadLines(int count)
    {
        for (int i = 0; i < count; i++)
        {
            string? line;
            try
            {
                line = _reader.ReadLine();
            }
            catch (Exception ex) when (ex is IOException or UnauthorizedAccessException)
            {
                throw new CliException($"Cannot read \"{DisplayName}\": {ex.Message}");
            }
            if (line is null)
            {
                return false;
            }
            _lineNumber++;
            _lines.Add(line);
        }
        return true;
    }

    /// <summary>True when the parser stopped at the very end of the block: the last statement is not finished yet.</summary>
    private bool AtEnd(InstructionParseException ex) => ex.Line == _lines.Count && ex.Column == _lines[^1].Length + 1;

    /// <summary>
    /// Where each statement of <paramref name="text"/> starts (line offset from 0, column from 1): an instruction name outside
    /// parentheses, strings and <c>//</c> comments. The parser has accepted the text, so this only has to find the names.
    /// </summary>
    internal static List<(int Line, int Column)> StatementStarts(string text)
    {
        var starts = new List<(int, int)>();
        int depth = 0, line = 0, lineStart = 0;
        bool inString = false;
        for (int k = 0; k < text.Length; k++)
        {
            char c = text[k];
            char previous = k > 0 ? text[k - 1] : '\n';
            if (c == '\n')
            {
                line++;
                lineStart = k + 1;
                inString = false;
                continue;
            }
            if (inString)
            {
                if (c == '\\' && k + 1 < text.Length && text[k + 1] != '\n')
                {
                    k++;
                }
                else if (c == '"')
                {
                    inString = false;
                }
                continue;
            }
            if (c == '/' && k + 1 < text.Length && text[k + 1] == '/' && (depth == 0 || char.IsWhiteSpace(previous) || previous is ',' or '('))
            {
                while (k + 1 < text.Length && text[k + 1] != '\n')
                {
                    k++;
                }
                continue;
            }
            switch (c)
            {
                case '"' when depth > 0: inString = true; break;
                case '(': depth++; break;
                case ')': depth = Math.Max(0, depth - 1); break;
                default:
                    if (depth == 0 && char.IsAsciiLetter(c) && !(char.IsAsciiLetterOrDigit(previous) || previous == '_'))
                    {
                        starts.Add((line, k - lineStart + 1));
                    }
                    break;
            }
        }
        return starts;
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
