using System.Runtime.CompilerServices;

namespace Machina;

/// <summary>Receives the lines of one program file as a compiler writes them: kept in memory or written straight to disk.</summary>
internal abstract class LineSink
{
    /// <summary>Adds one line (without line ending).</summary>
    internal abstract void Add(string line);

    /// <summary>Adds the text of a builder as one line, without making a string of it where the sink can (hot compiler paths).</summary>
    internal virtual void Add(System.Text.StringBuilder line) => Add(line.ToString());

    /// <summary>Adds characters as one line, without making a string of them where the sink can (hot compiler paths).</summary>
    internal virtual void Add(ReadOnlySpan<char> line) => Add(new string(line));

    /// <summary>
    /// Adds characters as one line of which <paramref name="keptLength"/> characters from <paramref name="keptStart"/> are likely
    /// the same as in the line last given so (text a writer keeps from line to line): a sink that keeps lines in memory stores them
    /// once while they stay the same; the others add the line as <see cref="Add(ReadOnlySpan{char})"/> does.
    /// </summary>
    internal virtual void Add(ReadOnlySpan<char> line, int keptStart, int keptLength) => Add(line);

    // The scratch line of BeginAscii for a sink that does not hold bytes itself, and its characters.
    private byte[]? _asciiLine;
    private char[]? _asciiChars;

    /// <summary>
    /// Room for one line of ASCII bytes, at least <paramref name="most"/> long (no line ending): the writer fills its start and
    /// gives the length to <see cref="EndAscii"/>, which adds it as a line; without <see cref="EndAscii"/> nothing is added.
    /// Nothing else may be added in between. A sink that writes bytes hands out its own buffer, so the line is written once,
    /// in place (no characters narrowed per line); the others widen the bytes into characters (<see cref="Add(ReadOnlySpan{char})"/>).
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    internal virtual Span<byte> BeginAscii(int most)
    {
        if (_asciiLine is null || _asciiLine.Length < most)
        {
            _asciiLine = new byte[Math.Max(most, 256)];
            _asciiChars = new char[_asciiLine.Length];
        }
        return _asciiLine.AsSpan(0, most);
    }

    /// <summary>Adds the first <paramref name="length"/> bytes of the room <see cref="BeginAscii"/> gave as one line.</summary>
    internal virtual void EndAscii(int length)
    {
        Span<char> chars = _asciiChars.AsSpan(0, length);
        System.Text.Ascii.ToUtf16(AsciiLine(length), chars, out _);
        Add(chars);
    }

    /// <summary>The line of bytes <see cref="BeginAscii"/>'s scratch room holds, <paramref name="length"/> long.</summary>
    private protected ReadOnlySpan<byte> AsciiLine(int length) => _asciiLine.AsSpan(0, length);

    /// <summary>True when <see cref="StartOver"/> can drop the lines added so far.</summary>
    internal virtual bool CanStartOver => false;

    /// <summary>Drops every line added so far, so that the file is written again from its start (only when <see cref="CanStartOver"/>).</summary>
    internal virtual void StartOver() => throw new NotSupportedException("This sink cannot drop the lines it was given.");

    /// <summary>Adds several lines.</summary>
    internal void AddRange(IEnumerable<string> lines)
    {
        foreach (string line in lines)
        {
            Add(line);
        }
    }
}

/// <summary>Keeps lines in memory, packed into large blocks (see <see cref="PackedLines"/>).</summary>
internal sealed class ListLineSink : LineSink
{
    internal PackedLines Lines { get; } = new();

    internal override void Add(string line) => Lines.Add(line);

    internal override void Add(System.Text.StringBuilder line) => Lines.Add(line);

    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    internal override void Add(ReadOnlySpan<char> line) => Lines.Add(line);

    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    internal override void Add(ReadOnlySpan<char> line, int keptStart, int keptLength) => Lines.AddKept(line, keptStart, keptLength);

    /// <summary>Keeps the bytes as they are (an ASCII line is kept as bytes anyway).</summary>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    internal override void EndAscii(int length) => Lines.AddAscii(AsciiLine(length));
}

/// <summary>Writes lines to a text writer as they come.</summary>
internal sealed class WriterLineSink(TextWriter writer, string newLine) : LineSink
{
    /// <summary>Where the lines go.</summary>
    internal TextWriter Writer => writer;

    /// <summary>What ends each line.</summary>
    internal string NewLine => newLine;

    /// <summary>A file without a byte-order mark, which can be emptied and written again.</summary>
    internal override bool CanStartOver => writer is StreamWriter { BaseStream.CanSeek: true } stream && stream.Encoding.GetPreamble().Length == 0;

    internal override void StartOver()
    {
        if (!CanStartOver)
        {
            base.StartOver();
        }
        var stream = (StreamWriter)writer;
        stream.Flush();
        stream.BaseStream.SetLength(0);
        stream.BaseStream.Position = 0;
    }

    internal override void Add(string line)
    {
        writer.Write(line);
        writer.Write(newLine);
    }

    internal override void Add(System.Text.StringBuilder line)
    {
        writer.Write(line);
        writer.Write(newLine);
    }

    internal override void Add(ReadOnlySpan<char> line)
    {
        writer.Write(line);
        writer.Write(newLine);
    }
}
