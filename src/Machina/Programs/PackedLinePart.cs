using System.Runtime.CompilerServices;
using System.Text;

namespace Machina;

/// <summary>
/// One part of <see cref="PackedLines"/>: lines appended in order, their text in blocks (ASCII lines as bytes, others as
/// characters) and a table of where each line is, in fixed chunks of <see cref="ChunkSize"/> entries, so that the table grows
/// without ever being copied (only the first chunk grows by doubling, up to that size). Text that a writer keeps the same from
/// line to line (<see cref="AddKept"/>) is stored once and referred to by the lines that repeat it.
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

    /// <summary>Entries in each chunk of the table of lines: 4,096 entries of 20 bytes, under the large object heap's threshold.</summary>
    private const int ChunkShift = 12;

    private const int ChunkSize = 1 << ChunkShift;

    /// <summary>Entries the first chunk starts with.</summary>
    private const int FirstChunkSize = 16;

    private readonly Blocks<byte> _ascii = new();
    private readonly Blocks<char> _other = new();
    private readonly List<Line[]> _chunks = [];
    private Line[]? _last; // the last chunk of _chunks

    /// <summary>
    /// Where a line is: block index (≥ 0 in the ASCII blocks, ~index in the character blocks), start and length (of the whole
    /// line). A line that shares its kept text (<see cref="Kept"/> ≥ 0, an index into <see cref="_kept"/>) holds only the bytes
    /// before it (<see cref="Split"/> of them) and after it in its block; the kept text goes in between.
    /// </summary>
    private readonly record struct Line(int Block, int Start, int Length, int Split = 0, int Kept = -1)
    {
        internal bool IsAscii => Block >= 0;
    }

    /// <summary>
    /// Kept texts: ranges of ASCII bytes already stored as part of an earlier line (block, start, length), which later lines
    /// with the same text in the same place refer to instead of storing it again (<see cref="AddKept"/>).
    /// </summary>
    private readonly List<(int Block, int Start, int Length)> _kept = [];

    /// <summary>The kept text the next line is compared with: an index into <see cref="_kept"/>, or −1.</summary>
    private int _lastKept = -1;

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

    /// <summary>
    /// Appends a line of which <paramref name="keptLength"/> characters from <paramref name="keptStart"/> are likely the same as
    /// those of the line last given so (a RAPID move's orientation, configuration, speed, zone and tool: ~80 of its ~135
    /// characters in a toolpath). When they are, only the characters before and after them are stored and the line refers to
    /// the text stored once; otherwise the line is stored whole and its range becomes the text the next one is compared with.
    /// The line's text is the same either way.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    internal void AddKept(ReadOnlySpan<char> line, int keptStart, int keptLength)
    {
        if (_lastKept >= 0 && keptLength > 0)
        {
            (int keptBlock, int keptAt, int length) = _kept[_lastKept];
            if (length == keptLength && Ascii.Equals(_ascii.List[keptBlock].AsSpan(keptAt, length), line.Slice(keptStart, keptLength)))
            {
                ReadOnlySpan<char> head = line[..keptStart], tail = line[(keptStart + keptLength)..];
                int stored = head.Length + tail.Length;
                (int block, int start) = _ascii.Reserve(stored);
                Span<byte> room = _ascii.List[block].AsSpan(start, stored);
                if (Ascii.FromUtf16(head, room, out _) == System.Buffers.OperationStatus.Done
                    && Ascii.FromUtf16(tail, room[head.Length..], out _) == System.Buffers.OperationStatus.Done)
                {
                    Enter(new Line(block, start, line.Length, head.Length, _lastKept));
                    return;
                }
                _ascii.Unreserve(stored);
            }
        }
        Line entry = Add(line, false);
        if (entry.IsAscii && keptLength > 0)
        {
            _kept.Add((entry.Block, entry.Start + keptStart, keptLength));
            _lastKept = _kept.Count - 1;
        }
    }

    /// <summary>Appends a line.</summary>
    internal void Add(ReadOnlySpan<char> line) => Add(line, true);

    /// <summary>Appends a line and returns where it went; <paramref name="forget"/> ends the comparison of <see cref="AddKept"/>.</summary>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    private Line Add(ReadOnlySpan<char> line, bool forget)
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
        if (forget)
        {
            _lastKept = -1;
        }
        return entry;
    }

    /// <summary>Appends a line of ASCII bytes (copied into its block as it is).</summary>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    internal void AddAscii(ReadOnlySpan<byte> line)
    {
        (int block, int start) = _ascii.Reserve(line.Length);
        line.CopyTo(_ascii.List[block].AsSpan(start, line.Length));
        Enter(new Line(block, start, line.Length));
        _lastKept = -1;
    }

    /// <summary>Records where the line just stored is, as the next line.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)] // once per line: inlined into the optimised Add methods, not a tier-0 call
    private void Enter(Line entry)
    {
        int offset = Count & (ChunkSize - 1);
        Line[]? last = _last;
        if (last is null || offset == last.Length || (offset == 0 && Count > 0))
        {
            last = MakeRoom(offset);
        }
        last[offset] = entry;
        Count++;
        CharacterCount += entry.Length;
    }

    /// <summary>The chunk that takes the entry at <paramref name="offset"/>: a new one after a full one, or the first one grown.</summary>
    private Line[] MakeRoom(int offset)
    {
        if ((offset == 0 && Count > 0) || _chunks.Count == 0)
        {
            _chunks.Add(new Line[Count == 0 ? FirstChunkSize : ChunkSize]);
        }
        else
        {
            Line[] grown = new Line[offset * 2];
            _chunks[^1].CopyTo(grown, 0);
            _chunks[^1] = grown; // only the first chunk grows: the later ones are made full size
        }
        return _last = _chunks[^1];
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

    /// <summary>Characters this part holds in its blocks: <see cref="CharacterCount"/> less the kept text its lines refer to.</summary>
    internal long StoredCharacters()
    {
        long stored = 0;
        for (int i = 0; i < Count; i++)
        {
            Line line = At(i);
            stored += line.Length - (line.Kept >= 0 ? _kept[line.Kept].Length : 0);
        }
        return stored;
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
                WidenAscii(line, buffer);
                writer.Write(buffer.AsSpan(0, line.Length));
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
        // Where the kept text last widened is in the destination: the next line that refers to it copies those characters.
        int lastKept = -1, lastKeptAt = 0;
        for (int c = first >> ChunkShift; c < _chunks.Count && (c << ChunkShift) < end; c++)
        {
            Line[] chunk = _chunks[c];
            int from = Math.Max(0, first - (c << ChunkShift));
            int count = Math.Min(chunk.Length, end - (c << ChunkShift));
            for (int i = from; i < count; i++)
            {
                Line line = chunk[i];
                if (line.Kept >= 0)
                {
                    (int keptBlock, int keptStart, int keptLength) = _kept[line.Kept];
                    ReadOnlySpan<byte> own = _ascii.List[line.Block].AsSpan(line.Start, line.Length - keptLength);
                    int split = line.Split;
                    Ascii.ToUtf16(own[..split], destination[at..], out _);
                    if (line.Kept == lastKept)
                    {
                        destination.Slice(lastKeptAt, keptLength).CopyTo(destination[(at + split)..]);
                    }
                    else
                    {
                        Ascii.ToUtf16(_ascii.List[keptBlock].AsSpan(keptStart, keptLength), destination[(at + split)..], out _);
                        (lastKept, lastKeptAt) = (line.Kept, at + split);
                    }
                    Ascii.ToUtf16(own[split..], destination[(at + split + keptLength)..], out _);
                }
                else if (line.IsAscii)
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

    /// <summary>The bytes of an ASCII line that keeps all of its text in its block (<see cref="Line.Kept"/> &lt; 0).</summary>
    private ReadOnlySpan<byte> AsciiSpan(Line line) => _ascii.List[line.Block].AsSpan(line.Start, line.Length);

    private ReadOnlySpan<char> CharSpan(Line line) => _other.List[~line.Block].AsSpan(line.Start, line.Length);

    /// <summary>Widens an ASCII line (with its kept text, if it has one) into the first <see cref="Line.Length"/> characters of <paramref name="destination"/>.</summary>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)] // once per line of ToText: a call from the optimised copy loop, not tier-0 code
    private void WidenAscii(Line line, Span<char> destination)
    {
        if (line.Kept < 0)
        {
            Ascii.ToUtf16(AsciiSpan(line), destination, out _);
            return;
        }
        (int keptBlock, int keptStart, int keptLength) = _kept[line.Kept];
        ReadOnlySpan<byte> own = _ascii.List[line.Block].AsSpan(line.Start, line.Length - keptLength);
        Ascii.ToUtf16(own[..line.Split], destination, out _);
        Ascii.ToUtf16(_ascii.List[keptBlock].AsSpan(keptStart, keptLength), destination[line.Split..], out _);
        Ascii.ToUtf16(own[line.Split..], destination[(line.Split + keptLength)..], out _);
    }

    private string Text(Line line)
    {
        if (!line.IsAscii)
        {
            return new string(CharSpan(line));
        }
        if (line.Kept < 0)
        {
            return Encoding.ASCII.GetString(AsciiSpan(line));
        }
        return string.Create(line.Length, (this, line), static (destination, state) => state.Item1.WidenAscii(state.line, destination));
    }
}
