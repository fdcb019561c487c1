using System.Runtime.CompilerServices;
using System.Text;

namespace Machina;

/// <summary>
/// One part of <see cref="PackedLines"/>: lines appended in order, their text in blocks (ASCII lines as bytes, others as
/// characters) and a table of where each line is, in fixed chunks of <see cref="ChunkSize"/> entries, so that the table grows
/// without ever being copied (only the first chunk grows by doubling, up to that size).
/// </summary>
internal sealed class PackedLinePart
{
    /// <summary>Elements in the first block of each kind; each new block doubles, up to <see cref="MaxBlockBytes"/>, so short programs stay small.</summary>
    private const int FirstBlockSize = 1 << 10;

    /// <summary>
    /// Bytes in the largest blocks: 64 KiB (64 Ki ASCII characters, 32 Ki others), under the large object heap's threshold (85,000
    /// bytes). Blocks of 1 MB lived in the large object heap, and its small budget (about 3 MB before the first collection) made
    /// the blocks of one large compile trigger collections of every generation: two full, blocking or background, collections in
    /// the 400k-move job's <c>Compile()</c>, each marking every issued action (docs/performance.md, session 29). In the first
    /// generation they are allocated against its budget like any other object and are collected with it.
    /// </summary>
    internal const int MaxBlockBytes = 1 << 16;

    /// <summary>Entries in each chunk of the table of lines: 4,096 entries of 12 bytes, under the large object heap's threshold.</summary>
    private const int ChunkShift = 12;

    private const int ChunkSize = 1 << ChunkShift;

    /// <summary>Entries the first chunk starts with.</summary>
    private const int FirstChunkSize = 16;

    private readonly Blocks<byte> _ascii = new();
    private readonly Blocks<char> _other = new();
    private readonly List<Line[]> _chunks = [];

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
                int size = List.Count == 0 ? FirstBlockSize : Math.Min(MaxBlockBytes / Unsafe.SizeOf<T>(), List[^1].Length * 2);
                // Every element is written before it is read (a line's text, as it is added): no need to clear the block first.
                List.Add(GC.AllocateUninitializedArray<T>(Math.Max(size, length)));
                _used = 0;
            }
            int start = _used;
            _used += length;
            return (List.Count - 1, start);
        }

        /// <summary>Gives back the room of the last <see cref="Reserve"/> (of <paramref name="length"/> elements), unused.</summary>
        internal void Unreserve(int length) => _used -= length;
    }

    /// <summary>Number of lines.</summary>
    internal int Count { get; private set; }

    /// <summary>Total characters of all lines, without line endings.</summary>
    internal long CharacterCount { get; private set; }

    /// <summary>Appends a line.</summary>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    internal void Add(ReadOnlySpan<char> line)
    {
        Line entry;
        // Narrowed straight into its block, which checks as it goes (one pass over the line, not a check and then a copy); a line
        // that is not ASCII gives its room back and is kept as characters.
        (int block, int start) = _ascii.Reserve(line.Length);
        if (Ascii.FromUtf16(line, _ascii.List[block].AsSpan(start, line.Length), out _) == System.Buffers.OperationStatus.Done)
        {
            entry = new Line(block, start, line.Length);
        }
        else
        {
            _ascii.Unreserve(line.Length);
            (int otherBlock, int otherStart) = _other.Reserve(line.Length);
            line.CopyTo(_other.List[otherBlock].AsSpan(otherStart));
            entry = new Line(~otherBlock, otherStart, line.Length);
        }
        Enter(entry);
    }

    /// <summary>Appends a line of ASCII bytes (copied into its block as it is).</summary>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    internal void AddAscii(ReadOnlySpan<byte> line)
    {
        (int block, int start) = _ascii.Reserve(line.Length);
        line.CopyTo(_ascii.List[block].AsSpan(start, line.Length));
        Enter(new Line(block, start, line.Length));
    }

    /// <summary>Records where the line just stored is, as the next line.</summary>
    private void Enter(Line entry)
    {
        int offset = Count & (ChunkSize - 1);
        if ((offset == 0 && Count > 0) || _chunks.Count == 0)
        {
            _chunks.Add(new Line[Count == 0 ? FirstChunkSize : ChunkSize]);
        }
        else if (offset == _chunks[^1].Length)
        {
            Line[] grown = new Line[offset * 2];
            _chunks[^1].CopyTo(grown, 0);
            _chunks[^1] = grown; // only the first chunk grows: the later ones are made full size
        }
        _chunks[^1][offset] = entry;
        Count++;
        CharacterCount += entry.Length;
    }

    /// <summary>
    /// The first line whose text starts at least <paramref name="characters"/> characters into this part's text (each line followed
    /// by <paramref name="newLineLength"/> characters), and where it starts; <see cref="Count"/> and the part's length when none does.
    /// </summary>
    internal (int Line, long Start) LineFrom(long characters, int newLineLength)
    {
        long at = 0;
        for (int i = 0; i < Count; i++)
        {
            if (at >= characters)
            {
                return (i, at);
            }
            at += At(i).Length + newLineLength;
        }
        return (Count, at);
    }

    private Line At(int index) => _chunks[index >> ChunkShift][index & (ChunkSize - 1)];

    /// <summary>The text of the line at <paramref name="index"/> (in this part).</summary>
    internal string Text(int index) => Text(At(index));

    /// <summary>Writes every line followed by <paramref name="newLine"/>, through <paramref name="buffer"/> for ASCII lines that fit it.</summary>
    internal void WriteTo(TextWriter writer, string newLine, char[] buffer)
    {
        for (int i = 0; i < Count; i++)
        {
            Line line = At(i);
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

    /// <summary>
    /// Copies the lines from <paramref name="first"/> up to (not including) <paramref name="end"/>, each followed by
    /// <paramref name="newLine"/>, into <paramref name="destination"/> from <paramref name="at"/>; returns where it ended.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)] // runs once per ToText over every line: optimised from its first call
    internal int CopyTo(Span<char> destination, int at, string newLine, int first, int end)
    {
        for (int c = first >> ChunkShift; c < _chunks.Count && (c << ChunkShift) < end; c++)
        {
            Line[] chunk = _chunks[c];
            int from = Math.Max(0, first - (c << ChunkShift));
            int count = Math.Min(chunk.Length, end - (c << ChunkShift));
            for (int i = from; i < count; i++)
            {
                Line line = chunk[i];
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
        return at;
    }

    private ReadOnlySpan<byte> AsciiSpan(Line line) => _ascii.List[line.Block].AsSpan(line.Start, line.Length);

    private ReadOnlySpan<char> CharSpan(Line line) => _other.List[~line.Block].AsSpan(line.Start, line.Length);

    private string Text(Line line) => line.IsAscii ? Encoding.ASCII.GetString(AsciiSpan(line)) : new string(CharSpan(line));
}
