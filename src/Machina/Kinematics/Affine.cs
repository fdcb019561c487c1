namespace Machina;

/// <summary>A rigid transform as a 3×3 rotation matrix (row-major) and a translation in mm; the fast internal form used by the solvers.</summary>
internal readonly struct Affine
{
    internal readonly double R00, R01, R02, R10, R11, R12, R20, R21, R22, Px, Py, Pz;

    internal Affine(double r00, double r01, double r02, double r10, double r11, double r12, double r20, double r21, double r22, double px, double py, double pz)
    {
        R00 = r00; R01 = r01; R02 = r02; R10 = r10; R11 = r11; R12 = r12; R20 = r20; R21 = r21; R22 = r22; Px = px; Py = py; Pz = pz;
    }

    internal static Affine Identity => new(1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0);

    internal static Affine FromPose(Pose pose)
    {
        Rotation q = pose.Rotation;
        double w = q.W, x = q.X, y = q.Y, z = q.Z;
        return new Affine(
            1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y),
            2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x),
            2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y),
            pose.Position.X, pose.Position.Y, pose.Position.Z);
    }

    /// <summary>The pose of this transform, whose rotation must be a rotation matrix (a forward solve's: not checked again).</summary>
    /// <remarks>
    /// Every caller is a solver's forward kinematics, a product of rotations made from sines and cosines of finite angles, orthonormal to
    /// ~1e-14 where <see cref="RotationMatrix.IsRotation"/> allows 1e-6: the check could never fail, and it was a fifth of this method's cost.
    /// </remarks>
    internal Pose ToPose()
    {
        Rotation r = new RotationMatrix { M00 = R00, M01 = R01, M02 = R02, M10 = R10, M11 = R11, M12 = R12, M20 = R20, M21 = R21, M22 = R22 }.RotationOfRotation();
        return new Pose(new Vector(Px, Py, Pz), r);
    }

    /// <summary>Rotation about X by an angle given as cosine and sine.</summary>
    internal static Affine RotX(double c, double s) => new(1, 0, 0, 0, c, -s, 0, s, c, 0, 0, 0);

    /// <summary>Rotation about Y by an angle given as cosine and sine.</summary>
    internal static Affine RotY(double c, double s) => new(c, 0, s, 0, 1, 0, -s, 0, c, 0, 0, 0);

    /// <summary>Rotation about Z by an angle given as cosine and sine.</summary>
    internal static Affine RotZ(double c, double s) => new(c, -s, 0, s, c, 0, 0, 0, 1, 0, 0, 0);

    /// <summary>Standard Denavit–Hartenberg link transform Rz(θ)·Tz(d)·Tx(a)·Rx(α).</summary>
    /// <remarks>One <see cref="Math.SinCos"/>, which gives the bits of <see cref="Math.Cos"/> and <see cref="Math.Sin"/> (a forward kinematics takes six).</remarks>
    internal static Affine Dh(double theta, double d, double a, double cosAlpha, double sinAlpha)
    {
        (double st, double ct) = Math.SinCos(theta);
        return Dh(ct, st, d, a, cosAlpha, sinAlpha);
    }

    /// <summary>As <see cref="Dh(double, double, double, double, double)"/>, for a caller that has θ's cosine and sine already.</summary>
    internal static Affine Dh(double ct, double st, double d, double a, double cosAlpha, double sinAlpha)
    {
        return new Affine(
            ct, -st * cosAlpha, st * sinAlpha,
            st, ct * cosAlpha, -ct * sinAlpha,
            0, sinAlpha, cosAlpha,
            a * ct, a * st, d);
    }

    public static Affine operator *(Affine a, Affine b) => new(
        a.R00 * b.R00 + a.R01 * b.R10 + a.R02 * b.R20, a.R00 * b.R01 + a.R01 * b.R11 + a.R02 * b.R21, a.R00 * b.R02 + a.R01 * b.R12 + a.R02 * b.R22,
        a.R10 * b.R00 + a.R11 * b.R10 + a.R12 * b.R20, a.R10 * b.R01 + a.R11 * b.R11 + a.R12 * b.R21, a.R10 * b.R02 + a.R11 * b.R12 + a.R12 * b.R22,
        a.R20 * b.R00 + a.R21 * b.R10 + a.R22 * b.R20, a.R20 * b.R01 + a.R21 * b.R11 + a.R22 * b.R21, a.R20 * b.R02 + a.R21 * b.R12 + a.R22 * b.R22,
        a.R00 * b.Px + a.R01 * b.Py + a.R02 * b.Pz + a.Px, a.R10 * b.Px + a.R11 * b.Py + a.R12 * b.Pz + a.Py, a.R20 * b.Px + a.R21 * b.Py + a.R22 * b.Pz + a.Pz);

    /// <summary>The inverse of a rigid transform (transpose the rotation, rotate and negate the translation).</summary>
    internal Affine InverseRigid() => new(
        R00, R10, R20, R01, R11, R21, R02, R12, R22,
        -(R00 * Px + R10 * Py + R20 * Pz), -(R01 * Px + R11 * Py + R21 * Pz), -(R02 * Px + R12 * Py + R22 * Pz));

    /// <summary>The same rotation moved to a new translation.</summary>
    internal Affine WithTranslation(double px, double py, double pz) => new(R00, R01, R02, R10, R11, R12, R20, R21, R22, px, py, pz);
}
