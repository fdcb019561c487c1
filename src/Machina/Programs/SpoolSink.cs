using System.Runtime.CompilerServices;
using System.Text;

namespace Machina;

/// <summary>Lines kept aside by a compiler and moved into a file once what goes before them is known.</summary>
internal abstract class SpoolSink : LineSink, IDisposable
{
    /// <summary>Adds every spooled line, in order, to <paramref name="target"/>; the spool is empty afterwards.</summary>
    internal abstract void MoveTo(LineSink target);

    /// <summary>Drops the spooled lines (and any file holding them).</summary>
    public abstract void Dispose();
}

/// <summary>A spool in memory, for programs compiled in memory.</summary>
internal sealed class MemorySpool : SpoolSink
{
    private PackedLines _lines = new();

    internal override void Add(string line) => _lines.Add(line);

    internal override void Add(StringBuilder line) => _lines.Add(line);

    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    internal override void Add(ReadOnlySpan<char> line) => _lines.Add(line);

    internal override void MoveTo(LineSink target)
    {
        if (target is ListLineSink list)
        {
            list.Lines.AppendAdopting(_lines); // the blocks change hands: no line is copied or made a string
        }
        else
        {
            foreach (string line in _lines)
            {
                target.Add(line);
            }
        }
        _lines = new();
    }

    public override void Dispose() => _lines = new();
}

/// <summary>
/// A spool in a temporary file (the system's temporary folder), so that memory does not grow with the program. Moved into a file of the
/// same encoding and line ending as a plain byte copy; otherwise line by line.
/// </summary>
internal sealed class FileSpool : SpoolSink
{
    private readonly string _path;
    private readonly Encoding _encoding;
    private readonly string _newLine;
    private StreamWriter? _writer;

    internal FileSpool(string path, Encoding encoding, string newLine)
    {
        _path = path;
        _encoding = encoding;
        _newLine = newLine;
        // A spool must not start with a byte-order mark: its bytes go into the middle of a file.
        var stream = new FileStream(path, FileMode.Create, FileAccess.ReadWrite, FileShare.None, 1 << 16, FileOptions.DeleteOnClose);
        _writer = new StreamWriter(stream, encoding.GetPreamble().Length == 0 ? encoding : new UTF8Encoding(false), 1 << 16);
    }

    internal override void Add(string line)
    {
        StreamWriter writer = _writer ?? throw new ObjectDisposedException(nameof(FileSpool));
        writer.Write(line);
        writer.Write(_newLine);
    }

    internal override void Add(StringBuilder line)
    {
        StreamWriter writer = _writer ?? throw new ObjectDisposedException(nameof(FileSpool));
        writer.Write(line);
        writer.Write(_newLine);
    }

    internal override void Add(ReadOnlySpan<char> line)
    {
        StreamWriter writer = _writer ?? throw new ObjectDisposedException(nameof(FileSpool));
        writer.Write(line);
        writer.Write(_newLine);
    }

    internal override void MoveTo(LineSink target)
    {
        StreamWriter writer = _writer ?? throw new ObjectDisposedException(nameof(FileSpool));
        writer.Flush();
        Stream stream = writer.BaseStream;
        stream.Position = 0;
        if (target is WriterLineSink { Writer: StreamWriter output } sink && sink.NewLine == _newLine
            && ReferenceEquals(output.Encoding, writer.Encoding) && output.Encoding.GetPreamble().Length == 0)
        {
            output.Flush();
            stream.CopyTo(output.BaseStream);
        }
        else
        {
            using var reader = new StreamReader(stream, writer.Encoding, false, 1 << 16, leaveOpen: true);
            while (reader.ReadLine() is string line)
            {
                target.Add(line);
            }
        }
        stream.SetLength(0);
    }

    public override void Dispose()
    {
        _writer?.Dispose();
        _writer = null;
    }
}
