using Machina.Simulation.UrScript;

namespace Machina.Tests.Simulation.UrScript;

/// <summary>
/// <c>get_joint_speeds()</c>, the CB2 controllers' name for the actual joint speeds (as <c>get_joint_positions()</c>, which the
/// twin already had, is theirs for the joints). An older ROS <c>ur_driver</c> program (ros-industrial/universal_robot a8f1ceb,
/// <c>ur_driver/prog</c>, its state publisher thread) calls it; the twin refused that program with
/// "unknown function 'get_joint_speeds'" before it ran a line, then (with that name) at <c>get_tcp_force()</c>, which the Script
/// Manual still has (the wrench at the tool; zeros on a twin without a force model).
/// </summary>
public sealed class ThirdPartyUrJointSpeedsTests
{
    [Fact]
    public void GetJointSpeeds_ReadsTheActualJointSpeeds_StandingAndMoving_AndGetTcpForceNoWrench()
    {
        // In real time a speedj without t returns about when the speeds are reached (0.05 s at 10 rad/s²) and they go on until
        // stopj; the sleep of 0.2 s (real time: at least that) puts the reads after the ramp however late the thread runs (CI once
        // read 249 / -499 mrad/s right after speedj returned), so they read the speed motion's constant speeds.
        using var twin = new UrTwinController(new UrTwinOptions { RealTime = true });
        UrProgramState state = twin.Run("""
            def speeds():
              textmsg("standing ", get_joint_speeds())
              textmsg("wrench ", get_tcp_force())
              speedj([0.25, 0, 0, 0, -0.5, 0], 10.0)
              sleep(0.2)
              textmsg("moving j1 ", floor(get_joint_speeds()[0] * 1000 + 0.5))
              textmsg("moving j5 ", floor(get_joint_speeds()[4] * 1000 + 0.5))
              textmsg("actual j1 ", floor(get_actual_joint_speeds()[0] * 1000 + 0.5))
              stopj(10.0)
              textmsg("stopped ", get_joint_speeds())
            end
            """, CancellationToken.None);
        Assert.True(state == UrProgramState.Finished, twin.Error);

        Assert.Equal(["standing [0, 0, 0, 0, 0, 0]", "wrench p[0, 0, 0, 0, 0, 0]", "moving j1 250", "moving j5 -500", "actual j1 250", "stopped [0, 0, 0, 0, 0, 0]"],
            twin.Pendant.Lines.Where(l => l.StartsWith("standing ", StringComparison.Ordinal) || l.StartsWith("wrench ", StringComparison.Ordinal) || l.StartsWith("moving ", StringComparison.Ordinal)
                || l.StartsWith("actual ", StringComparison.Ordinal) || l.StartsWith("stopped ", StringComparison.Ordinal)));
    }
}
