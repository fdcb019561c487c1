using System.Runtime.CompilerServices;

namespace Machina;

/// <summary>Rotates the tool around its tip: to an orientation (<c>RotateTo</c>) or by an angle around an axis (<c>Rotate</c>).</summary>
public sealed record ActionRotation : RobotAction
{
    /// <summary>Creates a rotation from a rotation value.</summary>
    public ActionRotation(Rotation rotation, bool relative)
    {
        Rotation = rotation;
        Relative = relative;
        Request = rotation.ToAxisAngle().WithUnitAxis();
    }

    /// <summary>Creates a relative or absolute rotation of <paramref name="angleDegrees"/> around <paramref name="axis"/> (right-hand rule).</summary>
    public ActionRotation(Vector axis, double angleDegrees, bool relative)
    {
        axis.RequireFinite(nameof(axis));
        Num.Finite(angleDegrees, "angle");
        double length = axis.Length;
        if (length < 1e-9)
        {
            // The same limit as Rotation.FromAxisAngle: any longer axis, however short, gives a direction.
            throw new ArgumentException($"The rotation axis ({Num.R(axis.X)}, {Num.R(axis.Y)}, {Num.R(axis.Z)}) has no direction; give one such as (0, 0, 1).", nameof(axis));
        }
        Rotation = Rotation.FromAxisAngle(axis, angleDegrees);
        Relative = relative;
        // The length is known: the same quotients as Normalized() without its square root again (it scales huge axes first).
        Request = new AxisAngle(double.IsFinite(length) ? new Vector(axis.X / length, axis.Y / length, axis.Z / length) : axis.Normalized(), angleDegrees);
    }

    /// <summary>The rotation (relative) or the new orientation (absolute).</summary>
    public Rotation Rotation { get; }

    /// <summary>True to rotate by <see cref="Rotation"/>, false to rotate to it.</summary>
    public bool Relative { get; }

    /// <summary>The axis (unit length) and angle (degrees, as the user gave it) of the rotation.</summary>
    public AxisAngle Request { get; }

    /// <inheritdoc/>
    public override bool IsRelative => Relative;

    /// <inheritdoc/>
    public override ActionType Type => ActionType.Rotation;

    /// <inheritdoc/>
    public override string ToInstruction()
    {
        if (Relative)
        {
            Span<char> buffer = stackalloc char[MaxWrittenInstructionChars];
            return new string(buffer[..TryWriteInstruction(buffer)]);
        }
        Vector x = InstructionText.Axis(Rotation.XAxis), y = InstructionText.Axis(Rotation.YAxis);
        return InstructionText.Call("RotateTo", x.X, x.Y, x.Z, y.X, y.Y, y.Z);
    }

    /// <inheritdoc/>
    public override string Describe()
    {
        if (!Relative)
        {
            return $"Rotate to {Rotation.ToOrientationString()}";
        }
        Span<char> buffer = stackalloc char[MaxWrittenDescriptionChars];
        return new string(buffer[..TryWriteDescription(buffer)]);
    }

    /// <summary>A relative rotation's instruction, <c>Rotate(x,y,z,angle);</c> (lossless numbers, the axis without rounding noise).</summary>
    internal override int TryWriteInstruction(Span<char> destination)
    {
        if (!Relative)
        {
            return -1;
        }
        Vector axis = InstructionText.Axis(Request.Axis);
        return InstructionText.WriteCall(destination, "Rotate", axis.X, axis.Y, axis.Z, Request.Angle);
    }

    /// <summary>
    /// A relative rotation's description, <c>Rotate {angle} deg around [x, y, z]</c> (the angle as <see cref="Num.G"/> writes it,
    /// the axis with 3 decimals): a program that turns on every other line describes millions of them.
    /// </summary>
    internal override int TryWriteDescription(Span<char> destination)
    {
        if (!Relative)
        {
            return -1;
        }
        "Rotate ".CopyTo(destination);
        int at = 7;
        at += NumShortest.WriteGeneral(destination[at..], Request.Angle);
        " deg around ".CopyTo(destination[at..]);
        at += 12;
        return at + WriteAxis(destination[at..], Request.Axis);
    }

    /// <inheritdoc cref="TryWriteDescription"/>
    /// <remarks>The ASCII bytes of <see cref="TryWriteDescription"/>'s text; −1 also when a number takes .NET's general text.</remarks>
    internal override int TryWriteDescriptionAscii(Span<byte> destination)
    {
        if (!Relative)
        {
            return -1;
        }
        "Rotate "u8.CopyTo(destination);
        int at = 7;
        int written = NumShortest.TryWrite(destination[at..], Request.Angle);
        if (written < 0)
        {
            return -1;
        }
        at += written;
        " deg around "u8.CopyTo(destination[at..]);
        at += 12;
        written = IsAlongAnAxis(Request.Axis) ? WriteUnitAxis(destination[at..], Request.Axis) : DescriptionAscii.TryWriteVector(destination[at..], Request.Axis);
        return written < 0 ? -1 : at + written;
    }

    /// <summary>
    /// The axis as <see cref="Vector.WriteText"/> writes it (<c>[x, y, z]</c>, 3 decimals). An axis along X, Y or Z (each component
    /// exactly 0, 1 or -1: most turns of a toolpath) is written digit by digit: three numbers less to format per turn.
    /// </summary>
    internal static int WriteAxis(Span<char> destination, Vector axis) =>
        IsAlongAnAxis(axis) ? WriteUnitAxis(destination, axis) : axis.WriteText(destination, ", ");

    /// <summary>True when each component is exactly 0, 1 or -1 (<see cref="IsSignedDigit"/>).</summary>
    private static bool IsAlongAnAxis(Vector axis) => IsSignedDigit(axis.X) && IsSignedDigit(axis.Y) && IsSignedDigit(axis.Z);

    /// <summary>Writes an axis along X, Y or Z digit by digit, as characters or ASCII bytes; returns the count.</summary>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    private static int WriteUnitAxis<T>(Span<T> destination, Vector axis)
        where T : unmanaged, System.Numerics.IBinaryInteger<T>
    {
        int at = 0;
        destination[at++] = T.CreateTruncating('[');
        at = WriteSignedDigit(destination, at, axis.X);
        destination[at++] = T.CreateTruncating(',');
        destination[at++] = T.CreateTruncating(' ');
        at = WriteSignedDigit(destination, at, axis.Y);
        destination[at++] = T.CreateTruncating(',');
        destination[at++] = T.CreateTruncating(' ');
        at = WriteSignedDigit(destination, at, axis.Z);
        destination[at++] = T.CreateTruncating(']');
        return at;
    }

    /// <summary>True for 1, -1 and positive zero (negative zero takes the number writer, which decides its sign).</summary>
    private static bool IsSignedDigit(double value) => value == 1 || value == -1 || BitConverter.DoubleToInt64Bits(value) == 0;

    private static int WriteSignedDigit<T>(Span<T> destination, int at, double value)
        where T : unmanaged, System.Numerics.IBinaryInteger<T>
    {
        if (value < 0)
        {
            destination[at++] = T.CreateTruncating('-');
        }
        destination[at++] = T.CreateTruncating(value == 0 ? '0' : '1');
        return at;
    }

    /// <summary>Equal when both are relative or both absolute and the rotations agree within 1e-9 degrees.</summary>
    public bool Equals(ActionRotation? other) =>
        other is not null && Relative == other.Relative && Rotation.IsSimilar(other.Rotation, 1e-9);

    /// <inheritdoc/>
    public override int GetHashCode() => HashCode.Combine(Type, Relative);
}
