using System.Buffers.Binary;

namespace Machina;

/// <summary>
/// The UR driver protocol's numbers (spec online §7.2; docs/protocol-ur.md): big-endian int32 values scaled by fixed
/// factors. Unit conversion (mm → m, degrees → radians) is <see cref="UrScriptText"/>'s; this only scales to integers.
/// </summary>
internal static class UrWire
{
    /// <summary>Integers per metre (1 = 0.001 mm, driver 3.0; int32 holds ±2,147 m).</summary>
    public const double FactorMetre = 1_000_000;

    /// <summary>Integers per radian (1 = 1e-6 rad, driver 3.0; int32 holds ±2,147 rad).</summary>
    public const double FactorRadian = 1_000_000;

    /// <summary>Integers per second (1 = 1 ms).</summary>
    public const double FactorSecond = 1_000;

    /// <summary>Integers per kilogram (1 = 1 g).</summary>
    public const double FactorKilogram = 1_000;

    /// <summary>Integers per unit of analog output.</summary>
    public const double FactorAnalog = 1_000_000;

    /// <summary>Response code of the version (our driver): major, minor, patch, then <see cref="End"/>.</summary>
    public const int ResponseVersion = -50;

    /// <summary>Response code of the full pose: X Y Z RX RY RZ J1..J6, then <see cref="End"/>.</summary>
    public const int ResponseFullPose = -54;

    /// <summary>Response code of a read input: the read's id, the value × <see cref="FactorAnalog"/> (a digital input: 0 or 1,000,000), then <see cref="End"/>; just before the read's acknowledgement.</summary>
    public const int ResponseInput = -60;

    /// <summary>Ends a response.</summary>
    public const int End = int.MinValue;

    /// <summary>The RTDE output integer register where our driver publishes the last executed id.</summary>
    public const int ExecutedRegister = 24;

    /// <summary>The RTDE output integer register where our driver publishes the last received id.</summary>
    public const int ReceivedRegister = 25;

    /// <summary>The RTDE output integer register where each of our driver programs publishes its instance number when it starts.</summary>
    public const int InstanceRegister = 26;

    /// <summary>Millimetres to wire integers (0.001 mm).</summary>
    public static int Millimetres(double mm) => Scale(mm * UrScriptText.Mm * FactorMetre);

    /// <summary>Degrees to wire integers (1e-6 rad).</summary>
    public static int Degrees(double degrees) => Scale(degrees * UrScriptText.Rad * FactorRadian);

    /// <summary>Wire integers (0.001 mm) to millimetres.</summary>
    public static double ToMillimetres(int value) => value / FactorMetre / UrScriptText.Mm;

    /// <summary>Wire integers (1e-6 rad) to degrees.</summary>
    public static double ToDegrees(int value) => value / FactorRadian / UrScriptText.Rad;

    /// <summary>Rounds a scaled value to the nearest integer, refusing what int32 cannot carry.</summary>
    public static int Scale(double scaled) =>
        double.IsFinite(scaled) && Math.Abs(scaled) < int.MaxValue
            ? (int)Math.Round(scaled, MidpointRounding.AwayFromZero)
            : throw new ArgumentOutOfRangeException(nameof(scaled), scaled, "The value is too large for the UR driver protocol (32-bit integers).");

    /// <summary>Writes <paramref name="values"/> big-endian into <paramref name="into"/> and returns the bytes written.</summary>
    public static int Write(ReadOnlySpan<int> values, Span<byte> into)
    {
        for (int i = 0; i < values.Length; i++)
        {
            BinaryPrimitives.WriteInt32BigEndian(into[(i * 4)..], values[i]);
        }
        return values.Length * 4;
    }
}
