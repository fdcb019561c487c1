using System.Collections;

namespace Machina;

/// <summary>
/// The lines of an in-memory program file, packed one after the other into large character blocks instead of one string
/// object per line. A program of a million lines then holds a few dozen large arrays that the garbage collector never has
/// to copy, instead of a million small strings it copies from generation to generation while compiling; this roughly halves
/// the time to compile long toolpaths in memory. Reading a line creates its string.
/// </summary>
internal sealed class PackedLines : IReadOnlyList<string>
{
    /// <summary>Characters in the first block; each new block doubles, up to <see cref="MaxBlockSize"/>, so short programs stay small.</summary>
    private const int FirstBlockSize = 1 << 10;

    /// <summary>Characters in the largest blocks: 1 Mi chars (2 MB), large enough to live in the large object heap.</summary>
    private const int MaxBlockSize = 1 << 20;

    private readonly List<char[]> _blocks = [];
    private readonly List<Line> _lines = [];
    private int _used;

    private readonly record struct Line(int Block, int Start, int Length);

    /// <summary>Number of lines.</summary>
    public int Count => _lines.Count;

    /// <summary>Total characters of all lines, without line endings.</summary>
    internal long CharacterCount { get; private set; }

    /// <summary>The line at <paramref name="index"/> (a new string each time).</summary>
    public string this[int index] => new(Span(_lines[index]));

    /// <summary>Appends a line.</summary>
    internal void Add(ReadOnlySpan<char> line)
    {
        if (_blocks.Count == 0 || line.Length > _blocks[^1].Length - _used)
        {
            int size = _blocks.Count == 0 ? FirstBlockSize : Math.Min(MaxBlockSize, _blocks[^1].Length * 2);
            _blocks.Add(new char[Math.Max(size, line.Length)]);
            _used = 0;
        }
        line.CopyTo(_blocks[^1].AsSpan(_used));
        _lines.Add(new Line(_blocks.Count - 1, _used, line.Length));
        _used += line.Length;
        CharacterCount += line.Length;
    }

    /// <summary>Writes every line followed by <paramref name="newLine"/>, without creating strings.</summary>
    internal void WriteTo(TextWriter writer, string newLine)
    {
        foreach (Line line in _lines)
        {
            writer.Write(Span(line));
            writer.Write(newLine);
        }
    }

    /// <summary>Copies every line followed by <paramref name="newLine"/> into <paramref name="destination"/>, which must be exactly long enough.</summary>
    internal void CopyTo(Span<char> destination, string newLine)
    {
        int at = 0;
        foreach (Line line in _lines)
        {
            Span(line).CopyTo(destination[at..]);
            at += line.Length;
            newLine.CopyTo(destination[at..]);
            at += newLine.Length;
        }
    }

    private ReadOnlySpan<char> Span(Line line) => _blocks[line.Block].AsSpan(line.Start, line.Length);

    /// <inheritdoc/>
    public IEnumerator<string> GetEnumerator()
    {
        for (int i = 0; i < _lines.Count; i++)
        {
            yield return new string(Span(_lines[i]));
        }
    }

    IEnumerator IEnumerable.GetEnumerator() => GetEnumerator();
}
