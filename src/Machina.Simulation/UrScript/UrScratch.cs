namespace Machina.Simulation.UrScript;

/// <summary>
/// The argument and local arrays of one interpreter thread's calls, used again once a call has returned: a built-in reads its
/// arguments during the call and keeps none of them (<see cref="UrBuiltin"/>), and a function's frame ends with its call. A call
/// whose array is not given back (an error unwinding it) only leaves that array to the collector. One per thread of the program:
/// never shared between threads.
/// </summary>
internal sealed class UrScratch
{
    /// <summary>Arrays longer than this are not kept.</summary>
    private const int MaxLength = 16;

    /// <summary>Arrays kept per length: as many as calls of that length nest in one expression (movel(pose_of(read_ints(6)), …)).</summary>
    private const int PerLength = 8;

    private readonly object?[][][] _free = new object?[MaxLength + 1][][];
    private readonly int[] _count = new int[MaxLength + 1];

    /// <summary>A thread's arrays, none kept yet.</summary>
    public UrScratch()
    {
        for (int length = 1; length <= MaxLength; length++)
        {
            _free[length] = new object?[PerLength][];
        }
    }

    /// <summary>An array of <paramref name="length"/> empty slots.</summary>
    public object?[] Rent(int length)
    {
        if (length <= MaxLength && _count[length] > 0)
        {
            object?[][] free = _free[length];
            object?[] array = free[--_count[length]];
            free[_count[length]] = null!;
            return array;
        }
        return length == 0 ? [] : new object?[length];
    }

    /// <summary>Takes back an array from <see cref="Rent"/> once nothing refers to it any more; its slots are emptied.</summary>
    public void Return(object?[] array)
    {
        int length = array.Length;
        if (length == 0 || length > MaxLength)
        {
            return;
        }
        if (_count[length] < PerLength)
        {
            Array.Clear(array);
            _free[length][_count[length]++] = array;
        }
    }
}
