using SN = System.Numerics;

namespace Machina.Tests.Geometry;

public class YawPitchRollTests
{
    /// <summary>Oracle: intrinsic Z-Y′-X″ is the product Rz(yaw)·Ry(pitch)·Rx(roll) (Numerics' own YawPitchRoll turns yaw about Y, so it is not used).</summary>
    private static SN.Quaternion Zyx(double yaw, double pitch, double roll) =>
        Oracle.Axis(0, 0, 1, yaw) * Oracle.Axis(0, 1, 0, pitch) * Oracle.Axis(1, 0, 0, roll);

    [Fact]
    public void ToRotation_SpecExample_Quaternion()
    {
        Rotation r = new YawPitchRoll(10, 20, 30).ToRotation();
        Assert.Equal("[0.9515, 0.0381, 0.1893, 0.2393]", r.ToQuaternionString());
        Oracle.SameQuaternion(Zyx(30, 20, 10), r);
        Assert.Equal(r, Rotation.FromYawPitchRoll(30, 20, 10));
    }

    [Fact]
    public void Properties_ConstructorOrderRollPitchYaw_Aliases()
    {
        var e = new YawPitchRoll(10, 20, 30);
        Assert.Equal(10, e.Roll);
        Assert.Equal(20, e.Pitch);
        Assert.Equal(30, e.Yaw);
        Assert.Equal("EulerZYX[Z:30, Y:20, X:10]", e.ToString());
        Assert.Equal("EulerZYX[Z:0.123457, Y:0, X:-1.5]", new YawPitchRoll(-1.5, -0.0, 0.1234567).ToString());
    }

    [Fact]
    public void ToRotation_SingleAxes_MatchAxisRotations()
    {
        Oracle.SameRotation(Rotation.FromAxisAngle(Vector.ZAxis, 40), new YawPitchRoll(0, 0, 40).ToRotation(), 1e-12);
        Oracle.SameRotation(Rotation.FromAxisAngle(Vector.YAxis, 40), new YawPitchRoll(0, 40, 0).ToRotation(), 1e-12);
        Oracle.SameRotation(Rotation.FromAxisAngle(Vector.XAxis, 40), new YawPitchRoll(40, 0, 0).ToRotation(), 1e-12);
    }

    [Fact]
    public void ToRotation_Intrinsic_SecondTurnAboutNewAxis()
    {
        // Yaw 90 takes X to Y; pitch 90 about the new Y (world Y) then turns the new X to world −Z.
        Rotation r = Rotation.FromYawPitchRoll(90, 90, 0);
        Oracle.SameVector(new Vector(0, 0, -1), r.XAxis, 1e-15);
        Oracle.SameVector(new Vector(-1, 0, 0), r.YAxis, 1e-15);
    }

    [Fact]
    public void ToRotation_NonFinite_ThrowsArgumentException()
    {
        Assert.Throws<ArgumentException>(() => new YawPitchRoll(double.NaN, 0, 0).ToRotation());
        Assert.Throws<ArgumentException>(() => Rotation.FromYawPitchRoll(0, double.PositiveInfinity, 0));
    }

    [Fact]
    public void ToYawPitchRoll_Grid_MatchesNumericsAndRoundTrips()
    {
        var angles = new double[] { -180, -135, -90, -60, -30, -1e-7, 0, 1e-7, 15, 45, 89.999, 90, 120, 179.9, 180 };
        var pitches = new double[] { -90, -89.999999, -89.999, -60, -30, 0, 1e-9, 33, 75, 89.9, 89.999, 89.9999999, 90 };
        foreach (double yaw in angles)
        {
            foreach (double pitch in pitches)
            {
                foreach (double roll in angles)
                {
                    Rotation r = Rotation.FromYawPitchRoll(yaw, pitch, roll);
                    Oracle.SameQuaternion(Zyx(yaw, pitch, roll), r, 2e-6);
                    YawPitchRoll e = r.ToYawPitchRoll();
                    Assert.InRange(e.Pitch, -90, 90);
                    Assert.InRange(e.Yaw, -180, 180);
                    Assert.InRange(e.Roll, -180, 180);
                    Oracle.SameRotation(r, e.ToRotation(), 1e-7);
                }
            }
        }
    }

    [Fact]
    public void ToYawPitchRoll_OrdinaryAngles_RecoversSameAngles()
    {
        YawPitchRoll e = Rotation.FromYawPitchRoll(30, 20, 10).ToYawPitchRoll();
        Assert.Equal(30, e.Yaw, 10);
        Assert.Equal(20, e.Pitch, 10);
        Assert.Equal(10, e.Roll, 10);
        YawPitchRoll n = Rotation.FromYawPitchRoll(-170, -80, 135).ToYawPitchRoll();
        Assert.Equal(-170, n.Yaw, 10);
        Assert.Equal(-80, n.Pitch, 10);
        Assert.Equal(135, n.Roll, 10);
    }

    [Theory]
    [InlineData(40, 90, 10, 30)]
    [InlineData(-20, 90, 100, -120)]
    [InlineData(40, -90, 10, 50)]
    [InlineData(170, -90, 30, -160)]
    public void ToYawPitchRoll_GimbalLock_RollZeroYawCarriesTurn(double yaw, double pitch, double roll, double expectedYaw)
    {
        Rotation r = Rotation.FromYawPitchRoll(yaw, pitch, roll);
        YawPitchRoll e = r.ToYawPitchRoll();
        Assert.Equal(pitch, e.Pitch, 12);
        Assert.Equal(0, e.Roll, 12);
        Assert.Equal(expectedYaw, e.Yaw, 7);
        Oracle.SameRotation(r, e.ToRotation(), 1e-7);
    }

    [Fact]
    public void ToYawPitchRoll_NearGimbalLock_ReproducesRotation()
    {
        foreach (double pitch in new[] { 89.99, 89.999, 89.9999, 89.99999, -89.9999, -89.999999 })
        {
            Rotation r = Rotation.FromYawPitchRoll(25, pitch, -35);
            YawPitchRoll e = r.ToYawPitchRoll();
            Assert.Equal(pitch, e.Pitch, 7);
            Oracle.SameRotation(r, e.ToRotation(), 1e-8);
        }
    }

    [Fact]
    public void ToYawPitchRoll_Presets_HandDerived()
    {
        YawPitchRoll id = Rotation.Identity.ToYawPitchRoll();
        Assert.Equal(new YawPitchRoll(0, 0, 0), id);
        YawPitchRoll fy = Rotation.FlippedAroundY.ToYawPitchRoll();
        Assert.Equal(0, fy.Pitch, 12);
        Assert.Equal(180, Math.Abs(fy.Yaw), 12);
        Assert.Equal(180, Math.Abs(fy.Roll), 12);
        Oracle.SameRotation(Rotation.FlippedAroundY, fy.ToRotation(), 1e-12);
    }
}
