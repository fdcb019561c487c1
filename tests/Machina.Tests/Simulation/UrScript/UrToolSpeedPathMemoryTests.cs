using Machina.Simulation.Twin;
using Machina.Simulation.UrScript;

namespace Machina.Tests.Simulation.UrScript;

/// <summary>
/// An open-ended speedl's way (<see cref="UrToolSpeedPath"/>) is asked for where the arm is now, as time goes on: it keeps the
/// samples it can still be asked for, not every sample since the call (it held them all, unbounded over a speedl of hours).
/// No clock: the way is asked for its times directly.
/// </summary>
public sealed class UrToolSpeedPathMemoryTests
{
    private static readonly Joints Start = new(0, -90, 90, -90, -90, 0);

    /// <summary>
    /// speedl at 0.1 mm/s along y (a sample every 0.5 s, the longest step) asked for every half second for 600 s: it used to hold
    /// 1,201 samples; now about what the last second and one chunk need, and the joints it gives still put the tool on its line.
    /// </summary>
    [Fact]
    public void OpenEndedSpeedl_AskedAsTimeGoesOn_HoldsOnlyTheRecentSamples()
    {
        using var twin = new UrTwinController(new UrTwinOptions { StartJoints = Start });
        var way = new UrToolSpeedPath(twin.Arm, Start, default, default, new Vector(0, 0.1, 0), default, 0);
        for (int k = 0; k <= 1200; k++)
        {
            way.At(k * 0.5);
        }
        Assert.InRange(way.HeldSamples, 1, 64 + 4);
        Assert.True(double.IsPositiveInfinity(way.LimitSeconds), $"the line ended at {way.LimitSeconds} s: {way.LimitReason}");

        foreach (double t in new[] { 599.9, 600.0, 600.25 })
        {
            Pose tool = twin.Arm.FlangeAt(way.At(t)) * twin.Arm.ToolCenter, due = way.PoseAt(t);
            Assert.Equal(due.Position.X, tool.Position.X, 6);
            Assert.Equal(due.Position.Y, tool.Position.Y, 6);
            Assert.Equal(due.Position.Z, tool.Position.Z, 6);
            Assert.Equal(twin.Arm.Tcp.Position.Y + 0.1 * t, tool.Position.Y, 6);
        }
    }
}
