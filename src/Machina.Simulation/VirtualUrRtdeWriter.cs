using System.Buffers.Binary;

namespace Machina.Simulation;

/// <summary>
/// Writes RTDE packages, reusing its buffer from package to package: <see cref="Begin"/> a type, the payload's values as the
/// RTDE guide gives them, then <see cref="End"/> sets the size and gives the package's bytes (valid until the next
/// <see cref="Begin"/>). A package past the 65,535 bytes its size field holds is refused.
/// </summary>
internal sealed class VirtualUrRtdeWriter(int payloadCapacity) : VirtualUrWriter(VirtualUrRtdePackages.HeaderSize + payloadCapacity)
{
    /// <summary>Starts a package of <paramref name="type"/>, dropping whatever was written before.</summary>
    public void Begin(byte type)
    {
        Restart(0);
        Zeros(2); // the size, set by End
        Byte(type);
    }

    /// <summary>The package written since <see cref="Begin"/>, its size set.</summary>
    /// <exception cref="InvalidDataException">The package is longer than the size field can say.</exception>
    public ReadOnlyMemory<byte> End()
    {
        if (Length > VirtualUrRtdePackages.MaxSize)
        {
            throw new InvalidDataException($"an RTDE package of {Length} bytes would pass the {VirtualUrRtdePackages.MaxSize} its size field holds.");
        }
        BinaryPrimitives.WriteUInt16BigEndian(Written(0, 2), (ushort)Length);
        return All;
    }
}
