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
