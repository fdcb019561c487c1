using System.Text;

namespace Machina;

/// <summary>
/// Writes the parts of URScript motions that repeat from one move to the next as <see cref="UrScriptText"/> does, keeping the
/// last text: a toolpath keeps its orientation and its speed, acceleration and blend radius over millions of moves, and the
/// rotation vector's three numbers (and its conversion) and the parameters' two or three are then copied instead of formatted again.
/// </summary>
/// <remarks>Values are compared by their bits, so that a text is reused only for exactly the numbers it was written from.</remarks>
internal sealed class UrRepeatedText
{
    private readonly StringBuilder _builder = new(64);
    private char[] _orientation = new char[64];
    private char[] _parameters = new char[64];
    private byte[] _orientationAscii = new byte[64];
    private byte[] _parametersAscii = new byte[64];
    private int _orientationLength, _parametersLength;
    private bool _orientationKnown;
    private long _w, _x, _y, _z;
    private bool _parametersKnown;
    private long _acceleration, _speed, _precision;
    private bool _joint;

    /// <summary>Appends the pose <c>p[x,y,z,rx,ry,rz]</c>; the same text as <see cref="UrScriptText.Pose"/>.</summary>
    internal StringBuilder Pose(StringBuilder sb, Vector position, Rotation rotation) =>
        sb.PosePosition(position).Append(Orientation(rotation));

    /// <summary>The second half of a pose, <c>,rx,ry,rz]</c>; the same text as <see cref="UrScriptText.PoseOrientation"/>.</summary>
    internal ReadOnlySpan<char> Orientation(Rotation rotation)
    {
        long w = Bits(rotation.W), x = Bits(rotation.X), y = Bits(rotation.Y), z = Bits(rotation.Z);
        if (!_orientationKnown || w != _w || x != _x || y != _y || z != _z)
        {
            _orientationLength = Keep(_builder.Clear().PoseOrientation(rotation), ref _orientation, ref _orientationAscii);
            (_orientationKnown, _w, _x, _y, _z) = (true, w, x, y, z);
        }
        return _orientation.AsSpan(0, _orientationLength);
    }

    /// <summary>Appends <c>, a=…, v=…, r=…)</c>; the same text as <see cref="UrScriptText.MotionParameters"/>.</summary>
    internal StringBuilder MotionParameters(StringBuilder sb, double acceleration, double speed, double precision, bool joint) =>
        sb.Append(Parameters(acceleration, speed, precision, joint));

    /// <summary>The text <c>, a=…, v=…, r=…)</c>; the same as <see cref="UrScriptText.MotionParameters"/>.</summary>
    internal ReadOnlySpan<char> Parameters(double acceleration, double speed, double precision, bool joint)
    {
        long a = Bits(acceleration), v = Bits(speed), r = Bits(precision);
        if (!_parametersKnown || a != _acceleration || v != _speed || r != _precision || joint != _joint)
        {
            _parametersLength = Keep(_builder.Clear().MotionParameters(acceleration, speed, precision, joint), ref _parameters, ref _parametersAscii);
            (_parametersKnown, _acceleration, _speed, _precision, _joint) = (true, a, v, r, joint);
        }
        return _parameters.AsSpan(0, _parametersLength);
    }

    /// <summary>The bytes of <see cref="Orientation"/> (numbers and fixed ASCII text), for a line written as bytes.</summary>
    internal ReadOnlySpan<byte> OrientationAscii(Rotation rotation)
    {
        Orientation(rotation);
        return _orientationAscii.AsSpan(0, _orientationLength);
    }

    /// <summary>The bytes of <see cref="Parameters"/> (numbers and fixed ASCII text), for a line written as bytes.</summary>
    internal ReadOnlySpan<byte> ParametersAscii(double acceleration, double speed, double precision, bool joint)
    {
        Parameters(acceleration, speed, precision, joint);
        return _parametersAscii.AsSpan(0, _parametersLength);
    }

    /// <summary>
    /// Copies the text into <paramref name="kept"/> and its bytes into <paramref name="ascii"/> (each grown when too short: a path that
    /// turns on every move reuses them); returns its length.
    /// </summary>
    private static int Keep(StringBuilder text, ref char[] kept, ref byte[] ascii)
    {
        if (kept.Length < text.Length)
        {
            kept = new char[text.Length * 2];
            ascii = new byte[kept.Length];
        }
        text.CopyTo(0, kept, text.Length);
        System.Text.Ascii.FromUtf16(kept.AsSpan(0, text.Length), ascii, out _);
        return text.Length;
    }

    private static long Bits(double value) => BitConverter.DoubleToInt64Bits(value);
}
