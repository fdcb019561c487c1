namespace Machina.Tests.Geometry;

public class VectorTests
{
    [Fact]
    public void Operators_Values_ComponentWise()
    {
        var a = new Vector(1, 2, 3);
        var b = new Vector(-4, 5, 0.5);
        Assert.Equal(new Vector(-3, 7, 3.5), a + b);
        Assert.Equal(new Vector(5, -3, 2.5), a - b);
        Assert.Equal(new Vector(-1, -2, -3), -a);
        Assert.Equal(new Vector(2, 4, 6), a * 2);
        Assert.Equal(new Vector(2, 4, 6), 2 * a);
        Assert.Equal(new Vector(0.5, 1, 1.5), a / 2);
    }

    [Fact]
    public void DotAndCross_KnownVectors_HandDerivedValues()
    {
        var a = new Vector(1, 2, 3);
        var b = new Vector(4, -5, 6);
        Assert.Equal(1 * 4 - 2 * 5 + 3 * 6, Vector.Dot(a, b));
        Assert.Equal(new Vector(2 * 6 + 3 * 5, 3 * 4 - 1 * 6, -1 * 5 - 2 * 4), Vector.Cross(a, b));
        Assert.Equal(Vector.ZAxis, Vector.Cross(Vector.XAxis, Vector.YAxis));
        Assert.Equal(Vector.XAxis, Vector.Cross(Vector.YAxis, Vector.ZAxis));
        Assert.Equal(Vector.YAxis, Vector.Cross(Vector.ZAxis, Vector.XAxis));
    }

    [Fact]
    public void LengthAndDistance_Pythagorean_Exact()
    {
        Assert.Equal(13, new Vector(3, 4, 12).Length);
        Assert.Equal(169, new Vector(3, 4, 12).SquaredLength);
        Assert.Equal(5, Vector.Distance(new Vector(1, 1, 1), new Vector(4, 5, 1)));
    }

    [Fact]
    public void AngleBetweenDegrees_KnownPairs_Degrees()
    {
        Assert.Equal(90, Vector.AngleBetweenDegrees(Vector.XAxis, Vector.YAxis), 12);
        Assert.Equal(180, Vector.AngleBetweenDegrees(Vector.XAxis, -Vector.XAxis), 12);
        Assert.Equal(45, Vector.AngleBetweenDegrees(new Vector(1, 0, 0), new Vector(3, 3, 0)), 12);
        Assert.Equal(0, Vector.AngleBetweenDegrees(Vector.Zero, Vector.XAxis));
        Assert.Equal(0, Vector.AngleBetweenDegrees(new Vector(1, 1e-9, 0), new Vector(1, 1e-9, 0)), 6);
    }

    [Fact]
    public void Normalized_NonUnit_UnitLengthSameDirection()
    {
        Vector n = new Vector(0, -3, 4).Normalized();
        Assert.Equal(new Vector(0, -0.6, 0.8), n);
        Assert.Equal(1, new Vector(1e-6, 2e-6, -3e-6).Normalized().Length, 14);
        Assert.Equal(1, new Vector(1e200, 1e200, 0).Normalized().Length, 14);
    }

    [Fact]
    public void Normalized_Zero_ThrowsArgumentException()
    {
        var ex = Assert.Throws<ArgumentException>(() => Vector.Zero.Normalized());
        Assert.Contains("no direction", ex.Message);
        Assert.Throws<ArgumentException>(() => new Vector(1e-12, 0, 0).Normalized());
        Assert.Throws<ArgumentException>(() => new Vector(double.NaN, 0, 0).Normalized());
        Assert.Throws<ArgumentException>(() => new Vector(double.PositiveInfinity, 0, 0).Normalized());
    }

    [Fact]
    public void IsSimilar_WithinAndBeyondTolerance_StrictComparison()
    {
        var a = new Vector(1, 2, 3);
        Assert.True(a.IsSimilar(new Vector(1 + 5e-7, 2 - 5e-7, 3)));
        Assert.False(a.IsSimilar(new Vector(1, 2, 3 + 2e-6)));
        Assert.True(a.IsSimilar(new Vector(1.05, 2, 3), 0.1));
        Assert.False(a.IsSimilar(new Vector(1.2, 2, 3), 0.1));
    }

    [Fact]
    public void IsZero_ThresholdAtOneMicrometre_True()
    {
        Assert.True(Vector.Zero.IsZero);
        Assert.True(new Vector(5e-7, 0, 0).IsZero);
        Assert.False(new Vector(2e-6, 0, 0).IsZero);
    }

    [Fact]
    public void ToString_Rounds3DecimalsAndCleansNegativeZero_Exact()
    {
        Assert.Equal("[400, 300, 500]", new Vector(400, 300, 500).ToString());
        Assert.Equal("[0.123, -1.5, 0]", new Vector(0.12345, -1.5, -0.0).ToString());
        Assert.Equal("[0, 0, 1234567.891]", new Vector(-0.0001, -0.0, 1234567.8912).ToString());
        Assert.Equal("[400,300,500.5]", new Vector(400, 300, 500.5).ToArrayString());
        Assert.Equal("[1, -2, 0]", ((Point)new Vector(1, -2, -0.0004)).ToString());
    }

    [Fact]
    public void ToString_UnderGermanCulture_UsesDecimalPoint()
    {
        string text = Oracle.UnderGerman(() => new Vector(1.5, -2.25, 1000.125).ToString() + new Point(0.5, 0, 0));
        Assert.Equal("[1.5, -2.25, 1000.125][0.5, 0, 0]", text);
    }

    [Fact]
    public void Point_ImplicitConversions_KeepValues()
    {
        Vector v = new Point(1, 2, 3);
        Point p = new Vector(4, 5, 6);
        Assert.Equal(new Vector(1, 2, 3), v);
        Assert.Equal(new Point(4, 5, 6), p);
        Assert.Equal(new Point(0, 0, 0), Point.Origin);
    }
}
