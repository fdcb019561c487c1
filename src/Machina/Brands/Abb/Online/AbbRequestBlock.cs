using System.Runtime.CompilerServices;

namespace Machina;

/// <summary>
/// The requests of one action, kept where it is declared (on the stack) instead of in a list: one action needs at most
/// <see cref="Capacity"/> (a Pop that changed speed, acceleration and zone), most need one.
/// </summary>
internal struct AbbRequestBlock
{
    /// <summary>The most requests one action is encoded into.</summary>
    public const int Capacity = 3;

    private Items _items;

    /// <summary>How many requests were added.</summary>
    public int Count { get; private set; }

    /// <summary>The request at <paramref name="index"/> (0 to <see cref="Count"/> - 1).</summary>
    public readonly AbbRequest this[int index] => (uint)index < (uint)Count
        ? _items[index]
        : throw new ArgumentOutOfRangeException(nameof(index), index, $"The block holds {Count} request(s).");

    /// <summary>Adds a request; more than <see cref="Capacity"/> is a bug of the encoder.</summary>
    public void Add(AbbRequest request)
    {
        if (Count == Capacity)
        {
            throw new InvalidOperationException($"One action is encoded into at most {Capacity} ABB requests.");
        }
        _items[Count++] = request;
    }

    [InlineArray(Capacity)]
    private struct Items
    {
        private AbbRequest _first;
    }
}
