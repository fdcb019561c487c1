namespace Machina.Tests.Geometry;

public class ExternalAxesTests
{
    [Fact]
    public void Constructor_NineE9OrMore_MeansUnset()
    {
        var e = new ExternalAxes(100, 9e9, 8.99e9, 1e12, null, -5);
        Assert.Equal(100, e[1]);
        Assert.Null(e[2]);
        Assert.Equal(8.99e9, e[3]);
        Assert.Null(e[4]);
        Assert.Null(e[5]);
        Assert.Equal(-5, e[6]);
        Assert.False(e.IsEmpty);
        Assert.True(new ExternalAxes(9e9, 9e9, 9e9, 9e9, 9e9, 9e9).IsEmpty);
    }

    [Fact]
    public void Default_AllUnset_EqualsNone()
    {
        Assert.True(default(ExternalAxes).IsEmpty);
        Assert.Equal(ExternalAxes.None, new ExternalAxes());
        Assert.Equal("[null, null, null, null, null, null]", ExternalAxes.None.ToString());
    }

    [Theory]
    [InlineData(0)]
    [InlineData(7)]
    [InlineData(-1)]
    public void Indexer_OutOfRange_Throws(int axis)
    {
        Assert.Throws<ArgumentOutOfRangeException>(() => new ExternalAxes(1)[axis]);
        Assert.Throws<ArgumentOutOfRangeException>(() => new ExternalAxes(1).With(axis, 5));
    }

    [Fact]
    public void With_SetsOneAxis_LeavesOthersAndOriginal()
    {
        var a = new ExternalAxes(1, 2);
        ExternalAxes b = a.With(6, 60).With(1, null).With(2, 9e9);
        Assert.Equal([1.0, 2, null, null, null, null], a.ToArray());
        Assert.Equal([null, null, null, null, null, 60.0], b.ToArray());
        Assert.NotEqual(a, b);
        Assert.Equal(b, new ExternalAxes(a6: 60));
        Assert.True(b == new ExternalAxes(a6: 60));
        Assert.Equal(b.GetHashCode(), new ExternalAxes(a6: 60).GetHashCode());
    }

    [Fact]
    public void NonFinite_ThrowsArgumentException()
    {
        Assert.Throws<ArgumentException>(() => new ExternalAxes(double.NaN));
        Assert.Throws<ArgumentException>(() => new ExternalAxes(1).With(3, double.NegativeInfinity));
    }

    [Fact]
    public void ToString_GermanCulture_InvariantThreeDecimals()
    {
        Assert.Equal("[100.5, null, -0.001, null, null, 0]", Oracle.UnderGerman(() => new ExternalAxes(100.5, null, -0.0012, null, null, -0.0).ToString()));
    }
}
