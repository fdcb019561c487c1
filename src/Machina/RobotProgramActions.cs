namespace Machina;

/// <summary>
/// The actions a robot issued offline, in order, for the next <c>Compile()</c>: appended in chunks of <see cref="ChunkSize"/>
/// that never move, where a doubling list copied every reference at each doubling and left the old arrays behind (a 400,000-move
/// program allocated 8.4 MB of arrays for 3.2 MB of references, 4 MB of them in one large-object array at the end; docs/performance.md,
/// session 28). Not thread-safe: the robot's issue lock guards it.
/// </summary>
internal sealed class RobotProgramActions
{
    /// <summary>References per full chunk: 64 KB, under the large-object heap's threshold (85,000 bytes).</summary>
    internal const int ChunkSize = 8192;

    // The first chunk grows as a list does (a program of ten actions holds no 64 KB array); the others are allocated full.
    private RobotAction[][] _chunks = [[]];
    private int _full; // chunks before the last one, each ChunkSize long and full

    /// <summary>Number of actions.</summary>
    internal int Count { get; private set; }

    /// <summary>Appends <paramref name="action"/>.</summary>
    internal void Add(RobotAction action)
    {
        RobotAction[] last = _chunks[_full];
        int at = Count - _full * ChunkSize;
        if (at == last.Length)
        {
            last = Grow(last);
            at = Count - _full * ChunkSize;
        }
        last[at] = action;
        Count++;
    }

    /// <summary>Makes room for one more action: a longer first chunk, or a new full-size chunk after a full one.</summary>
    private RobotAction[] Grow(RobotAction[] last)
    {
        if (last.Length < ChunkSize)
        {
            var longer = new RobotAction[Math.Min(ChunkSize, Math.Max(4, last.Length * 2))];
            last.CopyTo(longer, 0);
            _chunks[_full] = longer;
            return longer;
        }
        if (++_full == _chunks.Length)
        {
            Array.Resize(ref _chunks, _chunks.Length * 2);
        }
        return _chunks[_full] = new RobotAction[ChunkSize];
    }

    /// <summary>The actions, in order, in a new array of exactly <see cref="Count"/>.</summary>
    internal RobotAction[] ToArray()
    {
        var all = new RobotAction[Count];
        int copied = 0;
        for (int i = 0; copied < Count; i++)
        {
            int n = Math.Min(ChunkSize, Count - copied);
            Array.Copy(_chunks[i], 0, all, copied, n);
            copied += n;
        }
        return all;
    }

    /// <summary>The actions so far, sharing this list's chunks (nothing is copied but the chunks' references).</summary>
    internal RobotProgramSnapshot Snapshot() =>
        new(Count == 0 ? [] : _chunks[..(_full + (Count > _full * ChunkSize ? 1 : 0))], Count);

    /// <summary>Forgets every action (and the chunks that held them).</summary>
    internal void Clear()
    {
        _chunks = [[]];
        _full = 0;
        Count = 0;
    }
}
