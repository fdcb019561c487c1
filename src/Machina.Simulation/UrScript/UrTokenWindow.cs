namespace Machina.Simulation.UrScript;

/// <summary>
/// The tokens a parser reads, produced by the lexer as they are needed: indexes only grow, and only the last few tokens are
/// kept, so parsing a long program never holds all of its tokens at once.
/// </summary>
internal sealed class UrTokenWindow(IEnumerable<UrToken> tokens)
{
    /// <summary>How many tokens back from the newest one stay readable (the parser looks at most two ahead).</summary>
    private const int Size = 16;

    private readonly IEnumerator<UrToken> _source = tokens.GetEnumerator();
    private readonly UrToken[] _ring = new UrToken[Size];
    private int _count;
    private UrToken _last;

    /// <summary>The token at <paramref name="index"/> (0-based); past the end, the end token again.</summary>
    public UrToken this[int index]
    {
        get
        {
            while (_count <= index)
            {
                if (_source.MoveNext())
                {
                    _last = _source.Current;
                }
                _ring[_count % Size] = _last; // after the end, the end token repeats
                _count++;
            }
            if (index <= _count - Size)
            {
                throw new InvalidOperationException($"token {index} is no longer kept (the parser went back more than {Size} tokens)");
            }
            return _ring[index % Size];
        }
    }
}
