namespace Machina.Tests.Geometry;

/// <summary>
/// A unit quaternion's Euler angles and a forward solve's pose no longer check that their matrix is a rotation (session 35): they
/// must give the checked conversions' bits, and <see cref="RotationMatrix.IsRotation"/>, now on the nine entries, the vector form's
/// answer on matrices at its tolerance.
/// </summary>
public class RotationCheckSkippedTests
{
    [Fact]
    public void RotationToYawPitchRoll_IsTheCheckedMatrixConversion_BitForBit()
    {
        var random = new Random(3551);
        int locked = 0;
        for (int i = 0; i < 20000; i++)
        {
            double pitch = (i % 5) switch { 0 => 90, 1 => -90, 2 => 90 - 1e-7 * random.NextDouble(), _ => random.NextDouble() * 180 - 90 };
            Rotation r = i % 7 == 0
                ? Rotation.FromAxisAngle(new Vector(random.NextDouble() - 0.5, random.NextDouble() - 0.5, random.NextDouble() - 0.5), random.NextDouble() * 360 - 180)
                : Rotation.FromYawPitchRoll(random.NextDouble() * 360 - 180, pitch, random.NextDouble() * 360 - 180);
            YawPitchRoll got = r.ToYawPitchRoll();
            YawPitchRoll want = r.ToMatrix().ToYawPitchRoll();
            Assert.True(Bits(got.XAngle) == Bits(want.XAngle) && Bits(got.YAngle) == Bits(want.YAngle) && Bits(got.ZAngle) == Bits(want.ZAngle), $"{r}: {got} instead of {want}");
            locked += Math.Abs(got.Pitch) == 90 ? 1 : 0;
        }
        Assert.True(locked > 1000, $"only {locked} rotations at the lock");
    }

    [Fact]
    public void AffineToPose_IsTheCheckedMatrixConversion_BitForBit()
    {
        // Products of rotations about X, Y and Z as the ortho-parallel forward solve multiplies them, and the catalogue's forward solves.
        var random = new Random(3552);
        for (int i = 0; i < 20000; i++)
        {
            Affine a = Affine.RotZ(Cos(random, out double s1), s1) * Affine.RotY(Cos(random, out double s2), s2) * Affine.RotX(Cos(random, out double s3), s3)
                * Affine.RotY(Cos(random, out double s4), s4) * Affine.RotX(Cos(random, out double s5), s5);
            a = a.WithTranslation(random.NextDouble() * 2000 - 1000, random.NextDouble() * 2000 - 1000, random.NextDouble() * 2000);
            Pose got = a.ToPose();
            Rotation want = new RotationMatrix { M00 = a.R00, M01 = a.R01, M02 = a.R02, M10 = a.R10, M11 = a.R11, M12 = a.R12, M20 = a.R20, M21 = a.R21, M22 = a.R22 }.ToRotation();
            Assert.True(Same(got.Rotation, want), $"{got.Rotation} instead of {want}");
            Assert.True(Bits(got.Position.X) == Bits(a.Px) && Bits(got.Position.Y) == Bits(a.Py) && Bits(got.Position.Z) == Bits(a.Pz));
        }
        int solved = 0;
        foreach (RobotModel model in RobotModels.All)
        {
            for (int i = 0; i < 200; i++)
            {
                var j = new Joints(Angle(random), Angle(random), Angle(random), Angle(random), i % 3 == 0 ? 0 : Angle(random), Angle(random));
                Pose pose = model.Kinematics.Forward(j);
                // Every forward solve's matrix is a rotation far within the check's tolerance: the check could never have thrown.
                Assert.True(Affine.FromPose(pose) is var f && new RotationMatrix { M00 = f.R00, M01 = f.R01, M02 = f.R02, M10 = f.R10, M11 = f.R11, M12 = f.R12, M20 = f.R20, M21 = f.R21, M22 = f.R22 }.IsRotation);
                solved++;
            }
        }
        Assert.Equal(200 * RobotModels.All.Count, solved);
    }

    [Fact]
    public void IsRotation_IsTheVectorFormsAnswer_AtItsTolerance()
    {
        var random = new Random(3553);
        int yes = 0, no = 0;
        for (int i = 0; i < 40000; i++)
        {
            RotationMatrix b = Rotation.FromAxisAngle(new Vector(random.NextDouble() - 0.5, random.NextDouble() - 0.5, random.NextDouble() - 0.5), random.NextDouble() * 360).ToMatrix();
            // Entries moved by about the tolerance's square root: sums of squares land on both sides of 1e-6; some reflected.
            double s = (i % 3) switch { 0 => 3e-7, 1 => 6e-7, _ => 1e-6 };
            double E() => (random.NextDouble() * 2 - 1) * s;
            var m = new RotationMatrix
            {
                M00 = b.M00 + E(), M01 = b.M01 + E(), M02 = b.M02 + E(), M10 = b.M10 + E(), M11 = b.M11 + E(), M12 = b.M12 + E(),
                M20 = b.M20 + E(), M21 = b.M21 + E(), M22 = (i % 11 == 0 ? -b.M22 : b.M22) + E(),
            };
            bool want = VectorForm(m);
            Assert.Equal(want, m.IsRotation);
            yes += want ? 1 : 0;
            no += want ? 0 : 1;
        }
        Assert.True(yes > 5000 && no > 5000, $"{yes} rotations and {no} not: the tolerance's edge was not reached from both sides");
    }

    /// <summary>IsRotation as it was written before session 35: on the three axis vectors.</summary>
    private static bool VectorForm(RotationMatrix m)
    {
        const double tol = 1e-6;
        Vector x = m.XAxis, y = m.YAxis, z = m.ZAxis;
        return Math.Abs(x.SquaredLength - 1) < tol && Math.Abs(y.SquaredLength - 1) < tol && Math.Abs(z.SquaredLength - 1) < tol
            && Math.Abs(Vector.Dot(x, y)) < tol && Math.Abs(Vector.Dot(y, z)) < tol && Math.Abs(Vector.Dot(z, x)) < tol
            && Vector.Dot(Vector.Cross(x, y), z) > 0;
    }

    private static double Cos(Random random, out double sin)
    {
        (sin, double cos) = Math.SinCos(random.NextDouble() * 4 * Math.PI - 2 * Math.PI);
        return cos;
    }

    private static bool Same(Rotation a, Rotation b) => Bits(a.W) == Bits(b.W) && Bits(a.X) == Bits(b.X) && Bits(a.Y) == Bits(b.Y) && Bits(a.Z) == Bits(b.Z);

    private static long Bits(double d) => BitConverter.DoubleToInt64Bits(d);

    private static double Angle(Random random) => random.NextDouble() * 340 - 170;
}
