namespace Machina;

/// <summary>
/// Intrinsic Z-Y′-X″ (Tait–Bryan) Euler angles in degrees: yaw about Z, then pitch about the new Y, then roll about the new X;
/// R = Rz(yaw)·Ry(pitch)·Rx(roll). KUKA's A, B, C are (yaw, pitch, roll). Constructor order is (roll, pitch, yaw) as in the original.
/// </summary>
/// <param name="XAngle">Roll: rotation about X, degrees.</param>
/// <param name="YAngle">Pitch: rotation about Y, degrees.</param>
/// <param name="ZAngle">Yaw: rotation about Z, degrees.</param>
public readonly record struct YawPitchRoll(double XAngle, double YAngle, double ZAngle)
{
    /// <summary>Rotation about X (degrees), applied last.</summary>
    public double Roll => XAngle;

    /// <summary>Rotation about Y (degrees).</summary>
    public double Pitch => YAngle;

    /// <summary>Rotation about Z (degrees), applied first.</summary>
    public double Yaw => ZAngle;

    /// <summary>The rotation these angles describe: qz(yaw)·qy(pitch)·qx(roll).</summary>
    public Rotation ToRotation()
    {
        Num.Finite(XAngle, nameof(XAngle));
        Num.Finite(YAngle, nameof(YAngle));
        Num.Finite(ZAngle, nameof(ZAngle));
        double hx = XAngle * Angles.ToRadians / 2, hy = YAngle * Angles.ToRadians / 2, hz = ZAngle * Angles.ToRadians / 2;
        // Math.SinCos gives Math.Sin's and Math.Cos's bits (MathSinCosTests), in one call per angle: three where there were six.
        (double sx, double cx) = Math.SinCos(hx);
        (double sy, double cy) = Math.SinCos(hy);
        (double sz, double cz) = Math.SinCos(hz);
        return Rotation.FromQuaternion(
            cx * cy * cz + sx * sy * sz,
            sx * cy * cz - cx * sy * sz,
            cx * sy * cz + sx * cy * sz,
            cx * cy * sz - sx * sy * cz);
    }

    /// <summary>Rotation about X in degrees (the original's aviation name for <see cref="Roll"/>).</summary>
    public double Bank => XAngle;

    /// <summary>Rotation about Y in degrees (the original's aviation name for <see cref="Pitch"/>).</summary>
    public double Attitude => YAngle;

    /// <summary>Rotation about Z in degrees (the original's aviation name for <see cref="Yaw"/>).</summary>
    public double Heading => ZAngle;

    /// <summary>The 3×3 rotation matrix Rz(yaw)·Ry(pitch)·Rx(roll).</summary>
    public RotationMatrix ToRotationMatrix() => ToRotation().ToMatrix();

    /// <summary>The unit quaternion of these angles: qz(yaw)·qy(pitch)·qx(roll).</summary>
    public Quaternion ToQuaternion() => ToRotation().ToQuaternion();

    /// <summary>Text such as <c>EulerZYX[Z:30, Y:20, X:10]</c> (6 decimals).</summary>
    public override string ToString() => $"EulerZYX[Z:{Num.F(ZAngle, 6)}, Y:{Num.F(YAngle, 6)}, X:{Num.F(XAngle, 6)}]";
}
