using System.Runtime.CompilerServices;
using System.Collections;
using System.Text;

namespace Machina;

/// <summary>
/// The lines of an in-memory program file, packed one after the other into blocks of up to 64 KB instead of one string object
/// per line. A program of a million lines then holds a few thousand arrays of bytes, which hold no references for the garbage
/// collector to follow, instead of a million small strings. Lines of plain ASCII (all
/// robot code, most listings) are kept as one byte per character, half the memory of .NET strings; other lines as
/// characters. Reading a line creates its string.
/// </summary>
/// <remarks>
/// The lines are kept in one or more parts (<see cref="PackedLinePart"/>), each with its own blocks and its own table of where
/// each line is. <see cref="AppendAdopting"/> takes over another instance's parts as they are, so that moving a spool of a
/// million lines into a file copies nothing: neither its text nor its table (which, as one list, was copied into a new one
/// twice the size, 3.6 entries made per line kept).
/// </remarks>
internal sealed class PackedLines : IReadOnlyList<string>
{
    private readonly List<PackedLinePart> _parts = [];

    /// <summary>The part that takes the next line: the last one, or null when the last one was adopted (a new part is opened).</summary>
    private PackedLinePart? _open;

    private int _count;
    private int _longest;

    /// <summary>Number of lines.</summary>
    public int Count => _count;

    /// <summary>Total characters of all lines, without line endings.</summary>
    internal long CharacterCount { get; private set; }

    /// <summary>The line at <paramref name="index"/> (a new string each time).</summary>
    public string this[int index]
    {
        get
        {
            ArgumentOutOfRangeException.ThrowIfNegative(index);
            ArgumentOutOfRangeException.ThrowIfGreaterThanOrEqual(index, _count);
            foreach (PackedLinePart part in _parts)
            {
                if (index < part.Count)
                {
                    return part.Text(index);
                }
                index -= part.Count;
            }
            throw new InvalidOperationException("The parts hold fewer lines than counted.");
        }
    }

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
        (_open ?? Open()).Add(line);
        Counted(line.Length);
    }

    /// <summary>
    /// Appends a line of which <paramref name="keptLength"/> characters from <paramref name="keptStart"/> are likely the same as
    /// in the line last appended so: stored once while they stay the same (<see cref="PackedLinePart.AddKept"/>).
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    internal void AddKept(ReadOnlySpan<char> line, int keptStart, int keptLength)
    {
        (_open ?? Open()).AddKept(line, keptStart, keptLength);
        Counted(line.Length);
    }

    /// <summary>Appends a line of ASCII bytes.</summary>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    internal void AddAscii(ReadOnlySpan<byte> line)
    {
        (_open ?? Open()).AddAscii(line);
        Counted(line.Length);
    }

    /// <summary>Counts a line of <paramref name="length"/> characters just appended.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private void Counted(int length)
    {
        _count++;
        CharacterCount += length;
        _longest = Math.Max(_longest, length);
    }

    private PackedLinePart Open()
    {
        _open = new PackedLinePart();
        _parts.Add(_open);
        return _open;
    }

    /// <summary>
    /// Appends every line of <paramref name="other"/> by taking over its parts: no text is copied, no string made and no table
    /// of lines copied. <paramref name="other"/> must not be used afterwards.
    /// </summary>
    internal void AppendAdopting(PackedLines other)
    {
        foreach (PackedLinePart part in other._parts)
        {
            if (part.Count > 0)
            {
                _parts.Add(part);
            }
        }
        _open = null; // the next line goes into a part of this instance's own, after the adopted ones
        _count += other._count;
        CharacterCount += other.CharacterCount;
        _longest = Math.Max(_longest, other._longest);
    }

    /// <summary>Characters held in the blocks: <see cref="CharacterCount"/> less the kept text lines refer to (<see cref="AddKept"/>).</summary>
    internal long StoredCharacters() => _parts.Sum(p => p.StoredCharacters());

    /// <summary>Writes every line followed by <paramref name="newLine"/>, without creating strings.</summary>
    internal void WriteTo(TextWriter writer, string newLine)
    {
        char[] buffer = new char[Math.Min(_longest, PackedLinePart.MaxBlockBytes)];
        foreach (PackedLinePart part in _parts)
        {
            part.WriteTo(writer, newLine, buffer);
        }
    }

    /// <summary>Copies every line followed by <paramref name="newLine"/> into <paramref name="destination"/>, which must be exactly long enough.</summary>
    internal void CopyTo(Span<char> destination, string newLine) => CopyTo(destination, newLine, 0, _count);

    /// <summary>
    /// Copies the lines from <paramref name="first"/> up to (not including) <paramref name="end"/>, each followed by
    /// <paramref name="newLine"/>, into <paramref name="destination"/>, which must be exactly long enough for them.
    /// </summary>
    internal void CopyTo(Span<char> destination, string newLine, int first, int end)
    {
        int at = 0, line = 0;
        foreach (PackedLinePart part in _parts)
        {
            int from = Math.Max(first - line, 0), to = Math.Min(end - line, part.Count);
            if (from < to)
            {
                at = part.CopyTo(destination, at, newLine, from, to);
            }
            line += part.Count;
            if (line >= end)
            {
                break;
            }
        }
    }

    /// <summary>Texts from this many characters are copied by two threads (<see cref="CopyTo(Memory{char}, string)"/>).</summary>
    internal const int TwoThreadCharacters = 1 << 22;

    /// <summary>
    /// Copies every line followed by <paramref name="newLine"/> into <paramref name="destination"/>, which must be exactly long
    /// enough: a long text (from <see cref="TwoThreadCharacters"/>, with two processors or more) in two halves at once, the
    /// second on a thread of its own. Most of such a copy is the system's first touch of each fresh page of the new text (a
    /// 10^5-line program's 108 MB string is 27,000 page faults), and two threads take those on two processors.
    /// </summary>
    internal void CopyTo(Memory<char> destination, string newLine)
    {
        if (destination.Length < TwoThreadCharacters || Environment.ProcessorCount < 2)
        {
            CopyTo(destination.Span, newLine);
            return;
        }
        (int middle, long start) = Middle(newLine);
        Memory<char> second = destination[(int)start..];
        Exception? failed = null;
        var other = new Thread(() =>
        {
            try
            {
                CopyTo(second.Span, newLine, middle, _count);
            }
            catch (Exception e)
            {
                failed = e;
            }
        }) { IsBackground = true, Name = "Machina text copy" };
        other.Start();
        CopyTo(destination.Span[..(int)start], newLine, 0, middle);
        other.Join();
        if (failed is not null)
        {
            System.Runtime.ExceptionServices.ExceptionDispatchInfo.Throw(failed);
        }
    }

    /// <summary>The first line that starts at least half-way into the text (each line followed by <paramref name="newLine"/>), and where it starts.</summary>
    internal (int Line, long Start) Middle(string newLine)
    {
        long half = (CharacterCount + (long)_count * newLine.Length) / 2;
        long before = 0;
        int line = 0;
        foreach (PackedLinePart part in _parts)
        {
            long length = part.CharacterCount + (long)part.Count * newLine.Length;
            if (before + length > half)
            {
                (int inPart, long start) = part.LineFrom(half - before, newLine.Length);
                return (line + inPart, before + start);
            }
            before += length;
            line += part.Count;
        }
        return (_count, before);
    }

    /// <inheritdoc/>
    public IEnumerator<string> GetEnumerator()
    {
        foreach (PackedLinePart part in _parts)
        {
            for (int i = 0; i < part.Count; i++)
            {
                yield return part.Text(i);
            }
        }
    }

    IEnumerator IEnumerable.GetEnumerator() => GetEnumerator();
}
