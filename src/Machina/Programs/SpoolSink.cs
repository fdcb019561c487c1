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

    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    internal override void Add(ReadOnlySpan<char> line, int keptStart, int keptLength) => _lines.AddKept(line, keptStart, keptLength);

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
    private readonly Encoding _encoding;
    private readonly string _newLine;
    private readonly Stream _stream;
    private LineSink? _lines; // an AsciiFileSink for ASCII, else a WriterLineSink over a StreamWriter

    internal FileSpool(string path, Encoding encoding, string newLine)
    {
        _newLine = newLine;
        _stream = new FileStream(path, FileMode.Create, FileAccess.ReadWrite, FileShare.None, 1 << 16, FileOptions.DeleteOnClose);
        if (ReferenceEquals(encoding, Encoding.ASCII))
        {
            _encoding = encoding;
            _lines = new AsciiFileSink(_stream, newLine);
        }
        else
        {
            // A spool must not start with a byte-order mark: its bytes go into the middle of a file.
            _encoding = encoding.GetPreamble().Length == 0 ? encoding : new UTF8Encoding(false);
            _lines = new WriterLineSink(new StreamWriter(_stream, _encoding, 1 << 16), newLine);
        }
    }

    private LineSink Lines => _lines ?? throw new ObjectDisposedException(nameof(FileSpool));

    internal override void Add(string line) => Lines.Add(line);

    internal override void Add(StringBuilder line) => Lines.Add(line);

    internal override void Add(ReadOnlySpan<char> line) => Lines.Add(line);

    internal override void MoveTo(LineSink target)
    {
        LineSink lines = Lines;
        (lines as AsciiFileSink)?.Flush();
        ((lines as WriterLineSink)?.Writer as StreamWriter)?.Flush();
        _stream.Position = 0;
        if (target is AsciiFileSink ascii && lines is AsciiFileSink && ascii.NewLine == _newLine)
        {
            ascii.Flush();
            _stream.CopyTo(ascii.Stream);
        }
        else if (target is WriterLineSink { Writer: StreamWriter output } sink && sink.NewLine == _newLine
            && ReferenceEquals(output.Encoding, _encoding) && output.Encoding.GetPreamble().Length == 0)
        {
            output.Flush();
            _stream.CopyTo(output.BaseStream);
        }
        else
        {
            using var reader = new StreamReader(_stream, _encoding, false, 1 << 16, leaveOpen: true);
            while (reader.ReadLine() is string line)
            {
                target.Add(line);
            }
        }
        _stream.SetLength(0);
    }

    public override void Dispose()
    {
        if (_lines is null)
        {
            return;
        }
        (_lines as IDisposable)?.Dispose();
        ((_lines as WriterLineSink)?.Writer)?.Dispose();
        _lines = null;
    }
}
