namespace Machina;

/// <summary>
/// A 3×3 rotation matrix, row-major (M01 is row 0, column 1). Its columns are the axes of the rotated frame.
/// <c>new RotationMatrix()</c> is the identity, as in the original Machina; only <c>default</c> is all zeros (not a rotation).
/// </summary>
public readonly record struct RotationMatrix
{
    /// <summary>The identity matrix (no rotation), as in the original Machina.</summary>
    public RotationMatrix()
    {
        M00 = 1;
        M11 = 1;
        M22 = 1;
    }

    /// <summary>
    /// A rotation matrix from nine values in row order, made orthonormal as <see cref="FromRows"/> does (as in the original);
    /// a degenerate matrix is refused.
    /// </summary>
    public RotationMatrix(double m00, double m01, double m02, double m10, double m11, double m12, double m20, double m21, double m22) =>
        this = FromRows(m00, m01, m02, m10, m11, m12, m20, m21, m22);

    /// <summary>The matrix whose first two columns are <paramref name="xAxis"/> and <paramref name="yAxis"/>, made orthonormal (Z = X × Y).</summary>
    public RotationMatrix(Vector xAxis, Vector yAxis) => this = Rotation.FromAxes(xAxis, yAxis).ToMatrix();

    /// <summary>The identity matrix.</summary>
    public static RotationMatrix Identity => new();

    /// <summary>Row 0.</summary>
    public double M00 { get; init; }
    /// <summary>Row 0.</summary>
    public double M01 { get; init; }
    /// <summary>Row 0.</summary>
    public double M02 { get; init; }
    /// <summary>Row 1.</summary>
    public double M10 { get; init; }
    /// <summary>Row 1.</summary>
    public double M11 { get; init; }
    /// <summary>Row 1.</summary>
    public double M12 { get; init; }
    /// <summary>Row 2.</summary>
    public double M20 { get; init; }
    /// <summary>Row 2.</summary>
    public double M21 { get; init; }
    /// <summary>Row 2.</summary>
    public double M22 { get; init; }

    /// <summary>
    /// A rotation matrix from nine values in row order. The values are made orthonormal by keeping the first column's direction
    /// and the plane of the first two columns; a degenerate matrix is refused.
    /// </summary>
    public static RotationMatrix FromRows(double m00, double m01, double m02, double m10, double m11, double m12, double m20, double m21, double m22)
    {
        Rotation r = Rotation.FromAxes(new Vector(m00, m10, m20), new Vector(m01, m11, m21));
        return r.ToMatrix();
    }

    internal static RotationMatrix FromColumnsUnchecked(Vector x, Vector y, Vector z) => new()
    {
        M00 = x.X, M10 = x.Y, M20 = x.Z,
        M01 = y.X, M11 = y.Y, M21 = y.Z,
        M02 = z.X, M12 = z.Y, M22 = z.Z,
    };

    /// <summary>First column: the frame's X axis.</summary>
    public Vector XAxis => new(M00, M10, M20);

    /// <summary>Second column: the frame's Y axis.</summary>
    public Vector YAxis => new(M01, M11, M21);

    /// <summary>Third column: the frame's Z axis.</summary>
    public Vector ZAxis => new(M02, M12, M22);

    /// <summary>
    /// True when the columns are perpendicular unit vectors forming a right-handed frame (within 1e-6), as in every matrix
    /// Machina makes. <c>default</c> (all zeros) and matrices filled in by hand may not be.
    /// </summary>
    public bool IsRotation
    {
        get
        {
            // On the nine entries, no axis vectors: the same sums in the same order as Vector's SquaredLength, Dot and Cross give.
            const double tol = 1e-6;
            double x0 = M00, x1 = M10, x2 = M20, y0 = M01, y1 = M11, y2 = M21, z0 = M02, z1 = M12, z2 = M22;
            return Math.Abs(x0 * x0 + x1 * x1 + x2 * x2 - 1) < tol && Math.Abs(y0 * y0 + y1 * y1 + y2 * y2 - 1) < tol
                && Math.Abs(z0 * z0 + z1 * z1 + z2 * z2 - 1) < tol
                && Math.Abs(x0 * y0 + x1 * y1 + x2 * y2) < tol && Math.Abs(y0 * z0 + y1 * z1 + y2 * z2) < tol && Math.Abs(z0 * x0 + z1 * x1 + z2 * x2) < tol
                && (x1 * y2 - x2 * y1) * z0 + (x2 * y0 - x0 * y2) * z1 + (x0 * y1 - x1 * y0) * z2 > 0;
        }
    }

    private void RequireRotation()
    {
        if (!IsRotation)
        {
            throw new InvalidOperationException(
                $"{this} is not a rotation matrix: its columns must be perpendicular unit vectors of a right-handed frame. Build it with RotationMatrix.FromRows.");
        }
    }

    /// <summary>The quaternion of this matrix (Shepperd's method: numerically stable for every rotation).</summary>
    /// <exception cref="InvalidOperationException">The matrix is not a rotation (see <see cref="IsRotation"/>).</exception>
    public Rotation ToRotation()
    {
        RequireRotation();
        return RotationOfRotation();
    }

    /// <summary>
    /// <see cref="ToRotation"/> without its check, for a matrix known to be a rotation: one a solver's forward kinematics multiplied
    /// from sines and cosines (<c>Affine.ToPose</c>) or a unit quaternion's. The same bits as <see cref="ToRotation"/>.
    /// </summary>
    internal Rotation RotationOfRotation()
    {
        double trace = M00 + M11 + M22;
        double w, x, y, z;
        if (trace > 0)
        {
            double s = 2 * Math.Sqrt(trace + 1);
            w = 0.25 * s; x = (M21 - M12) / s; y = (M02 - M20) / s; z = (M10 - M01) / s;
        }
        else if (M00 > M11 && M00 > M22)
        {
            double s = 2 * Math.Sqrt(1 + M00 - M11 - M22);
            w = (M21 - M12) / s; x = 0.25 * s; y = (M01 + M10) / s; z = (M02 + M20) / s;
        }
        else if (M11 > M22)
        {
            double s = 2 * Math.Sqrt(1 + M11 - M00 - M22);
            w = (M02 - M20) / s; x = (M01 + M10) / s; y = 0.25 * s; z = (M12 + M21) / s;
        }
        else
        {
            double s = 2 * Math.Sqrt(1 + M22 - M00 - M11);
            w = (M10 - M01) / s; x = (M02 + M20) / s; y = (M12 + M21) / s; z = 0.25 * s;
        }
        return Rotation.FromQuaternion(w, x, y, z);
    }

    /// <summary>The unit quaternion of this matrix; see <see cref="ToRotation"/>.</summary>
    /// <exception cref="InvalidOperationException">The matrix is not a rotation (see <see cref="IsRotation"/>).</exception>
    public Quaternion ToQuaternion() => ToRotation().ToQuaternion();

    /// <summary>Rotation vector (axis × angle, degrees, angle in [0°, 180°]) of this matrix's rotation.</summary>
    /// <exception cref="InvalidOperationException">The matrix is not a rotation (see <see cref="IsRotation"/>).</exception>
    public RotationVector ToRotationVector() => ToRotation().ToRotationVector();

    /// <summary>True when every entry is within 1e-6 of the identity's.</summary>
    public bool IsIdentity() =>
        Math.Abs(M00 - 1) < 1e-6 && Math.Abs(M11 - 1) < 1e-6 && Math.Abs(M22 - 1) < 1e-6 && Math.Abs(M01) < 1e-6 && Math.Abs(M02) < 1e-6
        && Math.Abs(M10) < 1e-6 && Math.Abs(M12) < 1e-6 && Math.Abs(M20) < 1e-6 && Math.Abs(M21) < 1e-6;

    /// <summary>The determinant (1 for a rotation).</summary>
    public double Determinant() =>
        M00 * (M11 * M22 - M12 * M21) - M01 * (M10 * M22 - M12 * M20) + M02 * (M10 * M21 - M11 * M20);

    /// <summary>The matrix product <c>m1 · m2</c> (applies m2 in the frame of m1), as in the original.</summary>
    public static RotationMatrix Multiply(RotationMatrix m1, RotationMatrix m2) => new()
    {
        M00 = m1.M00 * m2.M00 + m1.M01 * m2.M10 + m1.M02 * m2.M20,
        M01 = m1.M00 * m2.M01 + m1.M01 * m2.M11 + m1.M02 * m2.M21,
        M02 = m1.M00 * m2.M02 + m1.M01 * m2.M12 + m1.M02 * m2.M22,
        M10 = m1.M10 * m2.M00 + m1.M11 * m2.M10 + m1.M12 * m2.M20,
        M11 = m1.M10 * m2.M01 + m1.M11 * m2.M11 + m1.M12 * m2.M21,
        M12 = m1.M10 * m2.M02 + m1.M11 * m2.M12 + m1.M12 * m2.M22,
        M20 = m1.M20 * m2.M00 + m1.M21 * m2.M10 + m1.M22 * m2.M20,
        M21 = m1.M20 * m2.M01 + m1.M21 * m2.M11 + m1.M22 * m2.M21,
        M22 = m1.M20 * m2.M02 + m1.M21 * m2.M12 + m1.M22 * m2.M22,
    };

    /// <summary>Axis and angle (degrees, in [0°, 180°]) of this matrix's rotation.</summary>
    /// <exception cref="InvalidOperationException">The matrix is not a rotation (see <see cref="IsRotation"/>).</exception>
    public AxisAngle ToAxisAngle() => ToRotation().ToAxisAngle();

    /// <summary>Intrinsic Z-Y′-X″ Euler angles in degrees; at pitch ±90° (gimbal lock) roll is set to 0 and yaw carries the whole turn.</summary>
    /// <exception cref="InvalidOperationException">The matrix is not a rotation (see <see cref="IsRotation"/>).</exception>
    public YawPitchRoll ToYawPitchRoll()
    {
        RequireRotation();
        return YawPitchRollOfRotation();
    }

    /// <summary>
    /// <see cref="ToYawPitchRoll"/> without its check, for a matrix known to be a rotation (<see cref="Rotation.ToYawPitchRoll"/>'s, of a
    /// unit quaternion). The same bits as <see cref="ToYawPitchRoll"/>.
    /// </summary>
    internal YawPitchRoll YawPitchRollOfRotation()
    {
        // cos(pitch) from the first column; only an exact lock (to ~1e-12 rad) takes the roll = 0 branch.
        double cosPitch = Math.Sqrt(M00 * M00 + M10 * M10);
        if (cosPitch < 1e-12)
        {
            return M20 < 0
                ? new YawPitchRoll(0, 90, Math.Atan2(M12, M02) * Angles.ToDegrees)
                : new YawPitchRoll(0, -90, Math.Atan2(-M12, -M02) * Angles.ToDegrees);
        }
        double yaw = Math.Atan2(M10, M00);
        double pitch = Math.Atan2(-M20, cosPitch);
        // Roll from Rz(−yaw)·R (its second row is [0, cos roll, −sin roll]), so that yaw and roll stay consistent near the lock.
        (double sy, double cy) = Math.SinCos(yaw); // the bits of Math.Sin and Math.Cos (MathSinCosTests), in one call
        double roll = Math.Atan2(sy * M02 - cy * M12, cy * M11 - sy * M01);
        return new YawPitchRoll(roll * Angles.ToDegrees, pitch * Angles.ToDegrees, yaw * Angles.ToDegrees);
    }

    /// <summary>Text such as <c>RotationMatrix[[1, 0, 0], [0, 1, 0], [0, 0, 1]]</c> (3 decimals).</summary>
    public override string ToString() =>
        $"RotationMatrix[[{Num.F(M00, 3)}, {Num.F(M01, 3)}, {Num.F(M02, 3)}], [{Num.F(M10, 3)}, {Num.F(M11, 3)}, {Num.F(M12, 3)}], [{Num.F(M20, 3)}, {Num.F(M21, 3)}, {Num.F(M22, 3)}]]";
}
