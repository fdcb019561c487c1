using System.Globalization;
using SN = System.Numerics;

namespace Machina.Tests.Geometry;

/// <summary>Independent references (System.Numerics) and comparison helpers for the geometry tests.</summary>
internal static class Oracle
{
    internal const double FloatTol = 1e-6;

    internal static SN.Quaternion Axis(double x, double y, double z, double degrees) =>
        SN.Quaternion.CreateFromAxisAngle(SN.Vector3.Normalize(new SN.Vector3((float)x, (float)y, (float)z)), (float)(degrees * Math.PI / 180));

    internal static Rotation ToRotation(SN.Quaternion q) => Rotation.FromQuaternion(q.W, q.X, q.Y, q.Z);

    /// <summary>Asserts two quaternions describe the same rotation, component-wise up to the q / −q sign.</summary>
    internal static void SameQuaternion(SN.Quaternion expected, Rotation actual, double tol = FloatTol)
    {
        double sign = expected.W * actual.W + expected.X * actual.X + expected.Y * actual.Y + expected.Z * actual.Z < 0 ? -1 : 1;
        Assert.Equal(expected.W, sign * actual.W, tol);
        Assert.Equal(expected.X, sign * actual.X, tol);
        Assert.Equal(expected.Y, sign * actual.Y, tol);
        Assert.Equal(expected.Z, sign * actual.Z, tol);
    }

    internal static void SameRotation(Rotation expected, Rotation actual, double tolDegrees = 1e-9) =>
        Assert.True(expected.IsSimilar(actual, tolDegrees), $"expected {expected} but got {actual} ({expected.AngleTo(actual)}° apart)");

    internal static void SameVector(Vector expected, Vector actual, double tol = 1e-12) =>
        Assert.True(expected.IsSimilar(actual, tol), $"expected ({expected.X:R}, {expected.Y:R}, {expected.Z:R}) but got ({actual.X:R}, {actual.Y:R}, {actual.Z:R})");

    internal static void SameVector(SN.Vector3 expected, Vector actual, double tol = FloatTol)
    {
        Assert.Equal(expected.X, actual.X, tol);
        Assert.Equal(expected.Y, actual.Y, tol);
        Assert.Equal(expected.Z, actual.Z, tol);
    }

    /// <summary>Runs <paramref name="action"/> with the current culture set to German (decimal comma), restoring it afterwards.</summary>
    internal static T UnderGerman<T>(Func<T> action)
    {
        CultureInfo before = CultureInfo.CurrentCulture;
        try
        {
            CultureInfo.CurrentCulture = new CultureInfo("de-DE");
            return action();
        }
        finally
        {
            CultureInfo.CurrentCulture = before;
        }
    }
}
