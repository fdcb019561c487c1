using Machina.Simulation;
using Machina.Simulation.Twin;
using Machina.Simulation.UrScript;
using Machina.Tests.Support;

namespace Machina.Tests.Simulation.UrScript;

/// <summary>
/// speedl as the Script Manual has it ("Accelerate linearly in Cartesian space and continue with constant tool speed"): the tool
/// keeps to its straight line however long the motion lasts. The twin used to turn the tool speed into joint speeds once at the
/// call and hold those, so the tool drifted off its line (millimetres after a few centimetres). Real time on a manual clock
/// only the test moves: no wall time is measured.
/// </summary>
public sealed class UrToolSpeedTests
{
    private static readonly TimeSpan Bound = TimeSpan.FromMinutes(1);
    private static readonly Joints Start = new(0, -90, 90, -90, -90, 0);

    private static Pose Tool(UrTwinController twin) => twin.Arm.FlangeAt(twin.JointsNow()) * twin.Arm.ToolCenter;

    /// <summary>
    /// speedl(0.05 m/s along y, a = 1, t = 4): 0.05 s of ramp (1.25 mm), then 0.05 m/s. After 2 s and 4 s the tool is that far
    /// along y, and x, z and its orientation are where they started (the old joint speeds put it 1.6 mm off after 2 s).
    /// </summary>
    [Fact]
    public void Speedl_LongRun_TheToolStaysOnItsStraightLine()
    {
        var clock = new ManualClock();
        using var twin = new UrTwinController(new UrTwinOptions { Time = clock, RealTime = true, StartJoints = Start });
        Pose start = twin.Arm.Tcp;
        Assert.True(twin.Start("""
            def line():
              speedl([0, 0.05, 0, 0, 0, 0], 1.0, 4.0)
              textmsg("returned")
              stopl(1.0)
            end
            """), twin.Error);
        Assert.True(SpinWait.SpinUntil(() => twin.Motion is not null && clock.HasTimerDueIn(TimeSpan.FromSeconds(4)), Bound),
            $"the speedl did not start: {twin.State} {twin.Error}");
        foreach (double seconds in new[] { 2.0, 4.0 })
        {
            clock.Advance(TimeSpan.FromSeconds(seconds == 2 ? 2 : 1.999));
            Pose at = Tool(twin);
            double along = seconds == 2 ? 1.25 + 50 * (2 - 0.05) : 1.25 + 50 * (3.999 - 0.05);
            Assert.Equal(start.Position.Y + along, at.Position.Y, 3);
            Assert.Equal(start.Position.X, at.Position.X, 3);
            Assert.Equal(start.Position.Z, at.Position.Z, 3);
            Assert.True(TwinRotation.AngleDegrees(start.Rotation, at.Rotation) < 0.001, $"the tool turned {TwinRotation.AngleDegrees(start.Rotation, at.Rotation)} degrees");
        }
        clock.Advance(TimeSpan.FromSeconds(0.001));
        Assert.True(SpinWait.SpinUntil(() => twin.Motion is { OpenEnded: false }, Bound), $"the stop did not start: {twin.State} {twin.Error}");
        clock.Advance(TimeSpan.FromSeconds(0.1));
        Assert.True(twin.WaitForEnd(Bound), "the program did not end");
        Assert.True(twin.State == UrProgramState.Finished, twin.Error);
        Pose end = twin.Arm.Tcp; // stopl slows it along the same line: 0.05 m/s to rest at 1 m/s² is 1.25 mm more
        Assert.Equal(start.Position.Y + 1.25 + 50 * 3.95 + 1.25, end.Position.Y, 2);
        Assert.Equal(start.Position.X, end.Position.X, 3);
        Assert.Equal(start.Position.Z, end.Position.Z, 3);
    }

    /// <summary>
    /// speedl straight up at 0.25 m/s goes on until the line leaves the arm's reach: the arm stops there with a protective stop,
    /// the tool still on its line (the old joint speeds curved it away and ran on until a joint's limit).
    /// </summary>
    [Fact]
    public void Speedl_OutOfReach_StopsOnTheLineWithAProtectiveStop()
    {
        var clock = new ManualClock();
        using var twin = new UrTwinController(new UrTwinOptions { Time = clock, RealTime = true, StartJoints = Start });
        Pose start = twin.Arm.Tcp;
        Assert.True(twin.Start("""
            def up():
              speedl([0, 0, 0.25, 0, 0, 0], 2.5)
              sleep(100)
            end
            """), twin.Error);
        Assert.True(SpinWait.SpinUntil(() => twin.Motion is not null && clock.HasTimerDueIn(TimeSpan.FromSeconds(0.1)), Bound),
            $"the speedl did not start: {twin.State} {twin.Error}");
        clock.Advance(TimeSpan.FromSeconds(0.1));
        Assert.True(SpinWait.SpinUntil(() => clock.HasTimerDueIn(TimeSpan.FromSeconds(100)), Bound), "the sleep did not start");
        clock.Advance(TimeSpan.FromSeconds(10));
        Assert.True(SpinWait.SpinUntil(() => twin.IsHeld, Bound), $"no protective stop: {string.Join(" | ", twin.Pendant.Lines)}");
        Assert.Contains(twin.Pendant.Lines, l => l.StartsWith("Protective stop: speedl: the tool's straight line leaves the arm's reach", StringComparison.Ordinal));
        Assert.Null(twin.Motion);
        Pose at = Tool(twin);
        Assert.True(at.Position.Z - start.Position.Z > 100, $"the tool rose only {at.Position.Z - start.Position.Z} mm");
        Assert.Equal(start.Position.X, at.Position.X, 2);
        Assert.Equal(start.Position.Y, at.Position.Y, 2);
    }
}
