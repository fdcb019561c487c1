using System.Buffers.Binary;
using System.Net.Sockets;

namespace Machina.Tests.Support;

/// <summary>Big-endian 32-bit integers on a raw socket, as UR scripts send and read them (tests speak the wire themselves).</summary>
internal static class WireInts
{
    /// <summary>Writes <paramref name="values"/> as big-endian 32-bit integers in one write.</summary>
    internal static async Task WriteAsync(NetworkStream stream, int[] values)
    {
        var bytes = new byte[values.Length * 4];
        for (int i = 0; i < values.Length; i++)
        {
            BinaryPrimitives.WriteInt32BigEndian(bytes.AsSpan(i * 4), values[i]);
        }
        await stream.WriteAsync(bytes);
    }

    /// <summary>Reads exactly <paramref name="count"/> big-endian 32-bit integers, waiting at most <paramref name="timeout"/>.</summary>
    internal static async Task<int[]> ReadAsync(NetworkStream stream, int count, TimeSpan timeout)
    {
        var bytes = new byte[count * 4];
        await stream.ReadExactlyAsync(bytes).AsTask().WaitAsync(timeout);
        return [.. Enumerable.Range(0, count).Select(i => BinaryPrimitives.ReadInt32BigEndian(bytes.AsSpan(i * 4)))];
    }
}
