namespace Machina.Tests.State;

/// <summary>Tolerance checks for poses (1e-9 mm and 1e-9 of an axis component).</summary>
internal static class PoseAssert
{
    internal static void Near(Vector expected, Vector? actual, double tolerance = 1e-9)
    {
        Assert.NotNull(actual);
        Vector a = actual.Value;
        Assert.True((a - expected).Length <= tolerance, $"Expected {expected.X}, {expected.Y}, {expected.Z} but was {a.X}, {a.Y}, {a.Z}.");
    }

    internal static void Axes(Vector xAxis, Vector zAxis, Rotation? actual)
    {
        Assert.NotNull(actual);
        Near(xAxis, actual.Value.XAxis);
        Near(zAxis, actual.Value.ZAxis);
    }

    internal static Robot AtFlipped(double x, double y, double z, string name = "Bot")
    {
        var bot = Robot.Create(name, RobotType.ABB);
        bot.MoveTo(x, y, z);
        return bot;
    }
}
