namespace Machina;

/// <summary>
/// The byte buffer of a message reader: received bytes are appended after the ones not yet returned (<c>start</c> to
/// <c>end</c>), which move to the front, or into a buffer twice as large, when the new bytes do not fit behind them.
/// </summary>
internal static class ReceiveBuffer
{
    /// <summary>
    /// Appends <paramref name="data"/> to <paramref name="buffer"/> after <paramref name="end"/>; returns how far the pending
    /// bytes moved towards the front (0 when they stayed), by which a reader's own positions in the buffer move too.
    /// </summary>
    public static int Append(ref byte[] buffer, ref int start, ref int end, ReadOnlySpan<byte> data)
    {
        int moved = 0;
        if (end + data.Length > buffer.Length)
        {
            int pending = end - start;
            if (pending + data.Length > buffer.Length)
            {
                var bigger = new byte[Math.Max(buffer.Length * 2, pending + data.Length)];
                buffer.AsSpan(start, pending).CopyTo(bigger);
                buffer = bigger;
            }
            else
            {
                buffer.AsSpan(start, pending).CopyTo(buffer);
            }
            moved = start;
            start = 0;
            end = pending;
        }
        data.CopyTo(buffer.AsSpan(end));
        end += data.Length;
        return moved;
    }
}
