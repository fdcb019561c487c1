using System.Runtime.CompilerServices;
using System.Collections;
using System.Text;

namespace Machina;

/// <summary>
/// The lines of an in-memory program file, packed one after the other into large blocks instead of one string object per
/// line. A program of a million lines then holds a few dozen large arrays that the garbage collector never has to copy,
/// instead of a million small strings it copies from generation to generation while compiling. Lines of plain ASCII (all
/// robot code, most listings) are kept as one byte per character, half the memory of .NET strings; other lines as
/// characters. Reading a line creates its string.
/// </summary>
internal sealed class PackedLines : IReadOnlyList<string>
{
    /// <summary>Elements in the first block of each kind; each new block doubles, up to <see cref="MaxBlockSize"/>, so short programs stay small.</summary>
    private const int FirstBlockSize = 1 << 10;

    /// <summary>Elements in the largest blocks: 1 Mi (1 MB of ASCII, 2 MB of characters), large enough to live in the large object heap.</summary>
    private const int MaxBlockSize = 1 << 20;

    private readonly Blocks<byte> _ascii = new();
    private readonly Blocks<char> _other = new();
    private readonly List<Line> _lines = [];
    private int _longest;

    /// <summary>Where a line is: block index (≥ 0 in the ASCII blocks, ~index in the character blocks), start and length.</summary>
    private readonly record struct Line(int Block, int Start, int Length)
    {
        internal bool IsAscii => Block >= 0;
    }

    /// <summary>A chain of blocks of one element type, filled in order.</summary>
    private sealed class Blocks<T>
    {
        internal readonly List<T[]> List = [];
        private int _used;

        /// <summary>Room for <paramref name="length"/> elements: the block index and the start within it.</summary>
        [MethodImpl(MethodImplOptions.AggressiveOptimization)]
        internal (int Block, int Start) Reserve(int length)
        {
            if (List.Count == 0 || length > List[^1].Length - _used)
            {
                int size = List.Count == 0 ? FirstBlockSize : Math.Min(MaxBlockSize, List[^1].Length * 2);
                List.Add(new T[Math.Max(size, length)]);
                _used = 0;
            }
            int start = _used;
            _used += length;
            return (List.Count - 1, start);
        }

        /// <summary>Takes over <paramref name="other"/>'s blocks after this chain's (no copy); returns the index its first block gets here.</summary>
        internal int Adopt(Blocks<T> other)
        {
            int offset = List.Count;
            if (other.List.Count > 0)
            {
                List.AddRange(other.List);
                _used = other._used;
            }
            return offset;
        }
    }

    /// <summary>Number of lines.</summary>
    public int Count => _lines.Count;

    /// <summary>Total characters of all lines, without line endings.</summary>
    internal long CharacterCount { get; private set; }

    /// <summary>The line at <paramref name="index"/> (a new string each time).</summary>
    public string this[int index] => Text(_lines[index]);

    /// <summary>Appends the text of a builder as a line, without making a string of it.</summary>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    internal void Add(StringBuilder line)
    {
        int length = line.Length;
        foreach (ReadOnlyMemory<char> chunk in line.GetChunks())
        {
            if (chunk.Length == length)
            {
                Add(chunk.Span); // the usual case: a builder that is reused has one chunk
                return;
            }
            break;
        }
        if (length == 0)
        {
            Add(ReadOnlySpan<char>.Empty);
            return;
        }
        char[] copy = System.Buffers.ArrayPool<char>.Shared.Rent(length);
        line.CopyTo(0, copy, length);
        Add(copy.AsSpan(0, length));
        System.Buffers.ArrayPool<char>.Shared.Return(copy);
    }

    /// <summary>Appends a line.</summary>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    internal void Add(ReadOnlySpan<char> line)
    {
        if (Ascii.IsValid(line))
        {
            (int block, int start) = _ascii.Reserve(line.Length);
            Ascii.FromUtf16(line, _ascii.List[block].AsSpan(start, line.Length), out _);
            _lines.Add(new Line(block, start, line.Length));
        }
        else
        {
            (int block, int start) = _other.Reserve(line.Length);
            line.CopyTo(_other.List[block].AsSpan(start));
            _lines.Add(new Line(~block, start, line.Length));
        }
        CharacterCount += line.Length;
        _longest = Math.Max(_longest, line.Length);
    }

    /// <summary>
    /// Appends every line of <paramref name="other"/> by taking over its blocks: no text is copied and no string made.
    /// <paramref name="other"/> must not be used afterwards.
    /// </summary>
    internal void AppendAdopting(PackedLines other)
    {
        int asciiOffset = _ascii.Adopt(other._ascii);
        int otherOffset = _other.Adopt(other._other);
        _lines.EnsureCapacity(_lines.Count + other._lines.Count);
        foreach (Line line in other._lines)
        {
            _lines.Add(line.IsAscii ? line with { Block = line.Block + asciiOffset } : line with { Block = ~(~line.Block + otherOffset) });
        }
        CharacterCount += other.CharacterCount;
        _longest = Math.Max(_longest, other._longest);
    }

    /// <summary>Writes every line followed by <paramref name="newLine"/>, without creating strings.</summary>
    internal void WriteTo(TextWriter writer, string newLine)
    {
        char[] buffer = new char[Math.Min(_longest, MaxBlockSize)];
        foreach (Line line in _lines)
        {
            if (line.IsAscii && line.Length <= buffer.Length)
            {
                Ascii.ToUtf16(AsciiSpan(line), buffer, out int written);
                writer.Write(buffer.AsSpan(0, written));
            }
            else if (line.IsAscii)
            {
                writer.Write(Text(line));
            }
            else
            {
                writer.Write(CharSpan(line));
            }
            writer.Write(newLine);
        }
    }

    /// <summary>Copies every line followed by <paramref name="newLine"/> into <paramref name="destination"/>, which must be exactly long enough.</summary>
    internal void CopyTo(Span<char> destination, string newLine)
    {
        int at = 0;
        foreach (Line line in _lines)
        {
            if (line.IsAscii)
            {
                Ascii.ToUtf16(AsciiSpan(line), destination[at..], out _);
            }
            else
            {
                CharSpan(line).CopyTo(destination[at..]);
            }
            at += line.Length;
            newLine.CopyTo(destination[at..]);
            at += newLine.Length;
        }
    }

    private ReadOnlySpan<byte> AsciiSpan(Line line) => _ascii.List[line.Block].AsSpan(line.Start, line.Length);

    private ReadOnlySpan<char> CharSpan(Line line) => _other.List[~line.Block].AsSpan(line.Start, line.Length);

    private string Text(Line line) => line.IsAscii ? Encoding.ASCII.GetString(AsciiSpan(line)) : new string(CharSpan(line));

    /// <inheritdoc/>
    public IEnumerator<string> GetEnumerator()
    {
        for (int i = 0; i < _lines.Count; i++)
        {
            yield return Text(_lines[i]);
        }
    }

    IEnumerator IEnumerable.GetEnumerator() => GetEnumerator();
}
