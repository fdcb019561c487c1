namespace Machina.Tests.Geometry;

public class JointsTests
{
    [Fact]
    public void Arithmetic_TwoJointSets_ComponentWise()
    {
        var a = new Joints(1, 2, 3, 4, 5, 6);
        var b = new Joints(10, -20, 30, -40, 50, 0.5);
        Assert.Equal(new Joints(11, -18, 33, -36, 55, 6.5), a + b);
        Assert.Equal(new Joints(-9, 22, -27, 44, -45, 5.5), a - b);
    }

    [Fact]
    public void Indexer_ZeroBased_ReturnsJoint()
    {
        var j = new Joints(1, 2, 3, 4, 5, 6);
        Assert.Equal([1.0, 2, 3, 4, 5, 6], Enumerable.Range(0, 6).Select(i => j[i]).ToArray());
        Assert.Throws<ArgumentOutOfRangeException>(() => j[6]);
        Assert.Throws<ArgumentOutOfRangeException>(() => j[-1]);
    }

    [Fact]
    public void FromArray_SixValues_RoundTripsToArray()
    {
        double[] values = [0, -90, 90, 0, 45.5, 180];
        Assert.Equal(values, Joints.FromArray(values).ToArray());
        var ex = Assert.Throws<ArgumentException>(() => Joints.FromArray([1, 2, 3]));
        Assert.Contains("exactly 6", ex.Message);
    }

    [Fact]
    public void ToString_ThreeDecimalsInvariant_Exact()
    {
        Assert.Equal("[0, 0, 0, 0, 90, 0]", (default(Joints) with { J5 = 90 }).ToString());
        Assert.Equal("[0.123, -1.5, 0, 100, -0.001, 2.5]", Oracle.UnderGerman(() => new Joints(0.12345, -1.5, -0.0, 100, -0.0012, 2.5).ToString()));
    }

    [Fact]
    public void IsSimilarAndIsFinite_Values_Expected()
    {
        var a = new Joints(1, 2, 3, 4, 5, 6);
        Assert.True(a.IsSimilar(a with { J6 = 6 + 5e-7 }));
        Assert.False(a.IsSimilar(a with { J6 = 6 + 2e-6 }));
        Assert.True(a.IsSimilar(a with { J1 = 1.4 }, 0.5));
        Assert.True(a.IsFinite);
        Assert.False((a with { J3 = double.NaN }).IsFinite);
        Assert.Throws<ArgumentException>(() => (a with { J3 = double.PositiveInfinity }).RequireFinite("joints"));
    }
}
