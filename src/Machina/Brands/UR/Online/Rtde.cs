using System.Buffers.Binary;

namespace Machina;

/// <summary>
/// Universal Robots' Real-Time Data Exchange (RTDE, port 30004), protocol version 2, as UR's RTDE guide describes it:
/// packages of a big-endian header (uint16 size including the header, uint8 type) and a payload.
/// </summary>
internal static class Rtde
{
    /// <summary>Bytes of a package header.</summary>
    public const int HeaderSize = 3;

    /// <summary>The protocol version Machina speaks.</summary>
    public const ushort ProtocolVersion = 2;

    /// <summary>'V': request protocol version (uint16) / accepted (uint8).</summary>
    public const byte RequestProtocolVersion = (byte)'V';

    /// <summary>'v': get the controller version / four uint32 (major, minor, bugfix, build).</summary>
    public const byte GetControllerVersion = (byte)'v';

    /// <summary>'M': text message.</summary>
    public const byte TextMessage = (byte)'M';

    /// <summary>'U': data package (recipe id, then the recipe's values).</summary>
    public const byte DataPackage = (byte)'U';

    /// <summary>'O': set up outputs (double frequency, comma-separated names) / recipe id and comma-separated types.</summary>
    public const byte SetupOutputs = (byte)'O';

    /// <summary>'I': set up inputs.</summary>
    public const byte SetupInputs = (byte)'I';

    /// <summary>'S': start sending data packages / accepted (uint8).</summary>
    public const byte Start = (byte)'S';

    /// <summary>'P': pause / accepted (uint8).</summary>
    public const byte Pause = (byte)'P';

    /// <summary>The type a variable not known to the controller gets in the setup reply.</summary>
    public const string NotFound = "NOT_FOUND";

    /// <summary>Writes a package (header and payload) into a new array.</summary>
    public static byte[] Package(byte type, ReadOnlySpan<byte> payload)
    {
        var bytes = new byte[HeaderSize + payload.Length];
        BinaryPrimitives.WriteUInt16BigEndian(bytes, (ushort)bytes.Length);
        bytes[2] = type;
        payload.CopyTo(bytes.AsSpan(HeaderSize));
        return bytes;
    }

    /// <summary>Bytes of one value of an RTDE type (VECTOR6D = 48, DOUBLE = 8, INT32/UINT32 = 4…), or 0 for an unknown type.</summary>
    public static int SizeOf(string type) => type switch
    {
        "VECTOR6D" => 48,
        "VECTOR3D" => 24,
        "VECTOR6INT32" or "VECTOR6UINT32" => 24,
        "DOUBLE" or "UINT64" => 8,
        "INT32" or "UINT32" => 4,
        "UINT8" or "BOOL" => 1,
        _ => 0,
    };
}

/// <summary>Cuts a byte stream into RTDE packages; a package may arrive in pieces or several in one read.</summary>
internal sealed class RtdePackageReader
{
    private byte[] _buffer = new byte[4096];
    private int _start;
    private int _length;

    /// <summary>Adds received bytes.</summary>
    public void Append(ReadOnlySpan<byte> data)
    {
        if (_start + _length + data.Length > _buffer.Length)
        {
            Array.Copy(_buffer, _start, _buffer, 0, _length);
            _start = 0;
            if (_length + data.Length > _buffer.Length)
            {
                Array.Resize(ref _buffer, Math.Max(_buffer.Length * 2, _length + data.Length));
            }
        }
        data.CopyTo(_buffer.AsSpan(_start + _length));
        _length += data.Length;
    }

    /// <summary>The next complete package (type and payload, valid until the next call), or false when more bytes are needed.</summary>
    public bool TryRead(out byte type, out ReadOnlySpan<byte> payload)
    {
        type = 0;
        payload = default;
        if (_length < Rtde.HeaderSize)
        {
            return false;
        }
        int size = BinaryPrimitives.ReadUInt16BigEndian(_buffer.AsSpan(_start));
        if (size < Rtde.HeaderSize)
        {
            throw new RobotConnectionException($"The controller sent an RTDE package of {size} bytes, shorter than its header.");
        }
        if (_length < size)
        {
            return false;
        }
        type = _buffer[_start + 2];
        payload = _buffer.AsSpan(_start + Rtde.HeaderSize, size - Rtde.HeaderSize);
        _start += size;
        _length -= size;
        if (_length == 0)
        {
            _start = 0;
        }
        return true;
    }
}
