namespace Machina.Simulation.Krl;

/// <summary>
/// The routines' frames (their locals' slots), reused from call to call: a frame lives from its routine's call to its END unless
/// an INTERRUPT DECL or a TRIGGER keeps it (their conditions, handlers' arguments and actions are evaluated in it later), so a
/// frame that nothing kept goes back, cleared, to a free list of its length when its routine ends, and the next call of a
/// routine with as many locals takes it. The driver's two routine calls an action made two frames (136 bytes).
/// </summary>
internal sealed partial class KrlMachine
{
    /// <summary>Frames with more slots than this are made for each call.</summary>
    private const int PooledFrameLength = 32;

    /// <summary>Free frames kept at most per length (deeper recursion makes new ones, as before).</summary>
    private const int PooledFramesPerLength = 8;

    /// <summary>For each length, the free frames (below its count).</summary>
    private readonly object[][]?[] _freeFrames = new object[][]?[PooledFrameLength + 1];
    private readonly int[] _freeFrameCounts = new int[PooledFrameLength + 1];

    /// <summary>How many times an INTERRUPT DECL or a TRIGGER kept the frame it ran in: a frame is given back only when this did not change during its call.</summary>
    private long _frameKeeps;

    /// <summary>A frame of <paramref name="length"/> empty slots for a call that starts now.</summary>
    private object[] TakeFrame(int length)
    {
        if (length == 0)
        {
            return [];
        }
        if (length <= PooledFrameLength && _freeFrameCounts[length] is > 0 and var count)
        {
            _freeFrameCounts[length] = count - 1;
            return _freeFrames[length]![count - 1];
        }
        return new object[length];
    }

    /// <summary>The call of <paramref name="frame"/> ended and nothing kept the frame: its slots are cleared and it is free again.</summary>
    private void GiveBackFrame(object[] frame)
    {
        int length = frame.Length;
        if (length == 0 || length > PooledFrameLength || _freeFrameCounts[length] == PooledFramesPerLength)
        {
            return;
        }
        Array.Clear(frame);
        object[][] free = _freeFrames[length] ??= new object[PooledFramesPerLength][];
        free[_freeFrameCounts[length]++] = frame;
    }

    /// <summary>An INTERRUPT DECL or a TRIGGER keeps the frame it ran in (and, conservatively, the frames of the calls under way).</summary>
    private void KeepFrame() => _frameKeeps++;
}
