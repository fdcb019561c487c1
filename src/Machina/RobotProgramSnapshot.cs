using System.Collections;

namespace Machina;

/// <summary>
/// The actions of a robot's offline program at one moment, for one <c>Compile()</c>: the issue list's own chunks, shared rather
/// than copied into one array (a 400,000-move program made a 3.2 MB large object for it, and that object alone forced a full
/// collection in the compile; docs/performance.md, session 29). Safe to share: the list only ever writes past its count, a
/// chunk it outgrows is replaced by a longer copy, and <c>Clear</c> starts new chunks.
/// </summary>
internal sealed class RobotProgramSnapshot : IEnumerable<RobotAction>
{
    private readonly RobotAction[][] _chunks;

    internal RobotProgramSnapshot(RobotAction[][] chunks, int count)
    {
        _chunks = chunks;
        Count = count;
    }

    /// <summary>Number of actions.</summary>
    internal int Count { get; }

    /// <summary>Number of chunks holding the actions.</summary>
    internal int ChunkCount => _chunks.Length;

    /// <summary>The actions of chunk <paramref name="index"/>, in order.</summary>
    internal ReadOnlySpan<RobotAction> Chunk(int index) =>
        _chunks[index].AsSpan(0, Math.Min(_chunks[index].Length, Count - index * RobotProgramActions.ChunkSize));

    /// <inheritdoc/>
    public IEnumerator<RobotAction> GetEnumerator()
    {
        for (int i = 0; i < _chunks.Length; i++)
        {
            RobotAction[] chunk = _chunks[i];
            int n = Math.Min(chunk.Length, Count - i * RobotProgramActions.ChunkSize);
            for (int j = 0; j < n; j++)
            {
                yield return chunk[j];
            }
        }
    }

    IEnumerator IEnumerable.GetEnumerator() => GetEnumerator();
}
