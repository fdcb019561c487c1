namespace Machina;

/// <summary>
/// The release policy of the paper: when the last block is used up and fewer than <see cref="PendingCount"/> released actions are
/// still unexecuted on the controller, a new block of <see cref="BlockSize"/> actions opens; buffered actions are released until the block is
/// used up (actions issued later join the open block at once). The defaults (8 and 3) keep at most 10 actions on the
/// controller and refill when 2 or fewer are left: the window of the original Machina.
/// </summary>
internal sealed class ReleaseWindow
{
    /// <summary>Default block size.</summary>
    internal const int DefaultBlockSize = 8;

    /// <summary>Default pending count.</summary>
    internal const int DefaultPendingCount = 3;

    private int _blockSize = DefaultBlockSize;
    private int _pendingCount = DefaultPendingCount;

    /// <summary>How many actions one release hands to the controller at most (1 or more).</summary>
    internal int BlockSize
    {
        get => Volatile.Read(ref _blockSize);
        set => Volatile.Write(ref _blockSize, RequirePositive(value, "block size", "blockSize"));
    }

    /// <summary>A block is released when fewer than this many released actions are unexecuted (1 or more).</summary>
    internal int PendingCount
    {
        get => Volatile.Read(ref _pendingCount);
        set => Volatile.Write(ref _pendingCount, RequirePositive(value, "pending count", "pendingCount"));
    }

    /// <summary>
    /// How many actions to release now, given how many are unexecuted on the device and how many wait in the buffer;
    /// <paramref name="credit"/> is what is left of the open block (kept by the caller, 0 at first) and is used up.
    /// </summary>
    internal int Take(int unexecuted, int buffered, ref int credit)
    {
        int blockSize = BlockSize;
        credit = credit == 0 && unexecuted < PendingCount ? blockSize : Math.Min(credit, blockSize);
        int count = Math.Min(credit, buffered);
        credit -= count;
        return count;
    }

    private static int RequirePositive(int value, string what, string parameter) => value >= 1
        ? value
        : throw new ArgumentOutOfRangeException(parameter, value, $"The {what} must be 1 or more; {value} was given.");
}
