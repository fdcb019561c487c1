using System.Text;

namespace Machina;

/// <summary>Where a compiler puts the files it writes: in memory (to build a <see cref="RobotProgram"/>) or straight into a folder.</summary>
internal abstract class ProgramOutput : IDisposable
{
    /// <summary>Opens a new file; lines added to the sink become its content, in order.</summary>
    internal abstract LineSink OpenFile(string name, string extension, Encoding encoding, string commentPrefix);

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
    internal RobotProgram ToProgram(string name, RobotType brand, IReadOnlyList<ProgramWarning> warnings) => new(
        name, brand, _files.Select(f => new RobotProgramFile(f.Name, f.Extension, f.Encoding, f.Comment, f.Sink.Lines)).ToArray(), warnings);
}

/// <summary>Writes files straight into a folder, without keeping their text in memory.</summary>
internal sealed class FolderProgramOutput(string folder, string newLine) : ProgramOutput
{
    private readonly List<StreamWriter> _writers = [];

    /// <summary>Paths of the files written.</summary>
    internal List<string> Paths { get; } = [];

    internal override LineSink OpenFile(string name, string extension, Encoding encoding, string commentPrefix)
    {
        Directory.CreateDirectory(folder);
        string path = Path.Combine(folder, name + "." + extension);
        var writer = new StreamWriter(path, append: false, encoding, bufferSize: 1 << 16);
        _writers.Add(writer);
        Paths.Add(path);
        return new WriterLineSink(writer, newLine);
    }

    public override void Dispose()
    {
        foreach (StreamWriter writer in _writers)
        {
            writer.Dispose();
        }
        _writers.Clear();
    }
}
