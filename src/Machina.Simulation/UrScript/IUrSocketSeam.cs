namespace Machina.Simulation.UrScript;

/// <summary>
/// Where a program's own sockets meet the world outside the interpreter, as on a real controller: the virtual UR watches what
/// the program reads and writes there (its inspection) and injects its faults at the program's writes (a delayed, cut or lost
/// acknowledgement is a fault on the driver's write of it).
/// </summary>
internal interface IUrSocketSeam
{
    /// <summary>A program's <c>socket_open</c> connected <paramref name="socket"/>; <paramref name="program"/> is cancelled when that program stops.</summary>
    void Opened(UrSocket socket, CancellationToken program);

    /// <summary>A <c>socket_read_binary_integer</c> on <paramref name="socket"/> gave <paramref name="values"/> ([n, v1 … vn]).</summary>
    void Read(UrSocket socket, UrList values);

    /// <summary>Writes <paramref name="bytes"/> for the program (blocking as long as the seam holds the write); false when they did not leave.</summary>
    bool Send(UrSocket socket, ReadOnlySpan<byte> bytes, CancellationToken program);
}
