namespace Machina.Tests.Actions;

/// <summary>A turn's description writes an axis along X, Y or Z digit by digit: the same text as the number writer's.</summary>
public class RotationAxisTextTests
{
    public static TheoryData<double, double, double> Axes()
    {
        var data = new TheoryData<double, double, double>();
        double[] values = [0, 1, -1, -0.0, 0.5, 1e-4, 0.9999996, -1.0000004];
        foreach (double x in values)
        {
            foreach (double y in values)
            {
                foreach (double z in values)
                {
                    data.Add(x, y, z);
                }
            }
        }
        return data;
    }

    [Theory]
    [MemberData(nameof(Axes))]
    public void WriteAxis_AnyAxis_WritesWhatTheNumberWriterWrites(double x, double y, double z)
    {
        var axis = new Vector(x, y, z);
        Span<char> general = stackalloc char[Vector.MaxTextChars];
        Span<char> written = stackalloc char[Vector.MaxTextChars];

        int expected = axis.WriteText(general, ", ");
        int length = ActionRotation.WriteAxis(written, axis);

        Assert.Equal(general[..expected].ToString(), written[..length].ToString());
    }

    [Theory]
    [InlineData(0, 0, 1, 90, "Rotate 90 deg around [0, 0, 1]")]
    [InlineData(0, -2, 0, 12.5, "Rotate 12.5 deg around [0, -1, 0]")]
    [InlineData(3, 4, 0, -30, "Rotate -30 deg around [0.6, 0.8, 0]")]
    public void Describe_RelativeTurn_NamesTheUnitAxis(double x, double y, double z, double angle, string expected)
    {
        Assert.Equal(expected, new ActionRotation(new Vector(x, y, z), angle, true).Describe());
    }
}
