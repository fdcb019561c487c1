namespace Machina.Simulation;

/// <summary>
/// The framing of UR's RTDE protocol as the virtual UR serves it, written from UR's RTDE guide: every package is a big-endian
/// uint16 size (header included), a uint8 type, then its payload. Every RTDE path of the twin reads its packages with a
/// <see cref="VirtualUrRtdeReader"/> and writes them with a <see cref="VirtualUrRtdeWriter"/>: requests, replies, input and
/// output data.
/// </summary>
internal static class VirtualUrRtdePackages
{
    /// <summary>Bytes of a package header: size (uint16) and type (uint8).</summary>
    public const int HeaderSize = 3;

    /// <summary>The largest package the size field can give, header included.</summary>
    public const int MaxSize = ushort.MaxValue;

    /// <summary>RTDE_REQUEST_PROTOCOL_VERSION ('V').</summary>
    public const byte RequestProtocolVersion = 86;

    /// <summary>RTDE_GET_URCONTROL_VERSION ('v').</summary>
    public const byte GetControllerVersion = 118;

    /// <summary>RTDE_TEXT_MESSAGE ('M').</summary>
    public const byte TextMessage = 77;

    /// <summary>RTDE_DATA_PACKAGE ('U').</summary>
    public const byte DataPackage = 85;

    /// <summary>RTDE_CONTROL_PACKAGE_SETUP_OUTPUTS ('O').</summary>
    public const byte SetupOutputs = 79;

    /// <summary>RTDE_CONTROL_PACKAGE_SETUP_INPUTS ('I').</summary>
    public const byte SetupInputs = 73;

    /// <summary>RTDE_CONTROL_PACKAGE_START ('S').</summary>
    public const byte Start = 83;

    /// <summary>RTDE_CONTROL_PACKAGE_PAUSE ('P').</summary>
    public const byte Pause = 80;

    /// <summary>The type a setup answers for a name the controller does not know.</summary>
    public const string NotFound = "NOT_FOUND";

    /// <summary>Bytes of one value of an RTDE type (the guide's data types); 0 for a name not found.</summary>
    public static int SizeOf(string type) => type switch
    {
        "BOOL" or "UINT8" => 1,
        "UINT32" or "INT32" => 4,
        "UINT64" or "DOUBLE" => 8,
        "VECTOR3D" => 24,
        "VECTOR6D" => 48,
        "VECTOR6INT32" or "VECTOR6UINT32" => 24,
        _ => 0,
    };
}
