using System.Text;

namespace Machina;

/// <summary>Where a compiler puts the files it writes: in memory (to build a <see cref="RobotProgram"/>) or straight into a folder.</summary>
internal abstract class ProgramOutput : IDisposable
{
    /// <summary>Opens a new file; lines added to the sink become its content, in order.</summary>
    internal abstract LineSink OpenFile(string name, string extension, Encoding encoding, string commentPrefix);

    /// <summary>
    /// Lines kept aside, to be placed later into a file of this output with <see cref="SpoolSink.MoveTo"/>: a compiler that
    /// learns its declarations while it writes its instructions writes them here, then the declarations, then these lines.
    /// </summary>
    internal abstract SpoolSink OpenSpool(Encoding encoding);

    /// <summary>Flushes and closes every file.</summary>
    public virtual void Dispose() { }
}

/// <summary>Collects files in memory.</summary>
internal sealed class MemoryProgramOutput : ProgramOutput
{
    private readonly List<(string Name, string Extension, Encoding Encoding, string Comment, ListLineSink Sink)> _files = [];

    internal override LineSink OpenFile(string name, string extension, Encoding encoding, string commentPrefix)
    {
        var sink = new ListLineSink();
        _files.Add((name, extension, encoding, commentPrefix, sink));
        return sink;
    }

    /// <summary>The program made of the files written so far.</summary>
    internal override SpoolSink OpenSpool(Encoding encoding) => new MemorySpool();

    internal RobotProgram ToProgram(string name, RobotType brand, IReadOnlyList<ProgramWarning> warnings) => new(
        name, brand, _files.Select(f => new RobotProgramFile(f.Name, f.Extension, f.Encoding, f.Comment, f.Sink.Lines)).ToArray(), warnings);
}

/// <summary>
/// Writes files straight into a folder, without keeping their text in memory. With <paramref name="replaceAtEnd"/> each file
/// is written under a temporary name and takes its real name only at <see cref="Commit"/>, so that a compilation that fails
/// half-way (an error on line 900,000 of an instruction file) leaves no truncated program and keeps any earlier one.
/// </summary>
internal sealed class FolderProgramOutput(string folder, string newLine, bool replaceAtEnd = false) : ProgramOutput
{
    /// <summary>Appended to a file's name while it is being written (with <c>replaceAtEnd</c>).</summary>
    internal const string PartialSuffix = ".partial";

    private readonly List<IDisposable> _writers = [];
    private bool _createdFolder;

    /// <summary>Paths of the files written.</summary>
    internal List<string> Paths { get; } = [];

    internal override LineSink OpenFile(string name, string extension, Encoding encoding, string commentPrefix)
    {
        if (!Directory.Exists(folder))
        {
            Directory.CreateDirectory(folder);
            _createdFolder = true;
        }
        string path = Path.Combine(folder, name + "." + extension);
        FileStream stream = OpenForWriting(replaceAtEnd ? path + PartialSuffix : path);
        Paths.Add(path);
        if (ReferenceEquals(encoding, Encoding.ASCII))
        {
            var ascii = new AsciiFileSink(stream, newLine); // the robot languages' files: bytes straight into its buffer
            _writers.Add(ascii);
            return ascii;
        }
        var writer = new StreamWriter(stream, encoding, bufferSize: 1 << 16);
        _writers.Add(writer);
        return new WriterLineSink(writer, newLine);
    }

    /// <summary>
    /// Opens a file for writing as <see cref="StreamWriter"/> does, but creates a new file without emptying it: on ext4, emptying
    /// a file (even a new, empty one, which .NET's <see cref="FileMode.Create"/> does) makes closing it write the whole file out
    /// at once, in the compile's own time (a tenth of a second for a 313 MB script). An existing file is still emptied, so that
    /// rewriting it in place keeps that protection; replacing one by renaming over it (<c>replaceAtEnd</c>) has its own.
    /// </summary>
    private static FileStream OpenForWriting(string path)
    {
        const int buffer = 4096;
        if (!File.Exists(path))
        {
            try
            {
                return new FileStream(path, FileMode.CreateNew, FileAccess.Write, FileShare.Read, buffer, FileOptions.SequentialScan);
            }
            catch (IOException) when (File.Exists(path))
            {
                // Created by someone else since the check: emptied and written over, as before.
            }
        }
        return new FileStream(path, FileMode.Create, FileAccess.Write, FileShare.Read, buffer, FileOptions.SequentialScan);
    }

    /// <summary>A spool in a temporary file (not in the output folder), deleted when it is closed.</summary>
    internal override SpoolSink OpenSpool(Encoding encoding)
    {
        return new FileSpool(Path.Combine(Path.GetTempPath(), "machina-" + Guid.NewGuid().ToString("N") + ".spool"), encoding, newLine);
    }

    /// <summary>
    /// Closes every file and, with <c>replaceAtEnd</c>, gives each its real name (replacing a file of that name). When a file
    /// cannot be closed (a full disk) or named (a folder has its name), nothing of this compile remains: the files it named
    /// already are removed too, and the error is thrown.
    /// </summary>
    internal void Commit()
    {
        CloseWriters(throwFirst: true);
        if (replaceAtEnd)
        {
            foreach (string path in Paths)
            {
                if (Directory.Exists(path))
                {
                    throw new IOException($"\"{path}\" is a folder; the program cannot be written under that name.");
                }
            }
            var named = new List<string>();
            try
            {
                foreach (string path in Paths)
                {
                    File.Move(path + PartialSuffix, path, overwrite: true);
                    named.Add(path);
                }
            }
            catch
            {
                named.ForEach(TryDelete);
                throw;
            }
        }
        _committed = true;
    }

    private bool _committed;

    public override void Dispose()
    {
        CloseWriters(throwFirst: false);
        if (replaceAtEnd && !_committed)
        {
            foreach (string path in Paths)
            {
                TryDelete(path + PartialSuffix);
            }
            try
            {
                if (_createdFolder && !Directory.EnumerateFileSystemEntries(folder).Any())
                {
                    Directory.Delete(folder); // a failed compile leaves nothing it made, not even an empty folder
                }
            }
            catch (Exception e) when (e is IOException or UnauthorizedAccessException)
            {
                // Left for the person to remove; the compile's own error is the one reported.
            }
        }
    }

    /// <summary>Closes every writer, even when one fails (a full disk fails the last flush); then throws the first failure if asked.</summary>
    private void CloseWriters(bool throwFirst)
    {
        Exception? first = null;
        foreach (IDisposable writer in _writers)
        {
            try
            {
                writer.Dispose();
            }
            catch (Exception e) when (e is IOException or UnauthorizedAccessException)
            {
                first ??= e;
            }
        }
        _writers.Clear();
        if (first is not null && throwFirst)
        {
            System.Runtime.ExceptionServices.ExceptionDispatchInfo.Throw(first);
        }
    }

    private static void TryDelete(string path)
    {
        try
        {
            File.Delete(path);
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            // Nothing more can be done; the compile's own error is the one reported.
        }
    }
}
