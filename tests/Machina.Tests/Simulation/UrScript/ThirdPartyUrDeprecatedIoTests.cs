using Machina.Simulation.UrScript;

namespace Machina.Tests.Simulation.UrScript;

/// <summary>
/// The deprecated I/O getters as the older controllers number them: <c>get_digital_in(n)</c>/<c>get_digital_out(n)</c> 0-9 (8-9 the
/// tool's 0-1), <c>get_analog_in(n)</c> 0-3 (2-3 the tool's), <c>get_analog_out(n)</c> 0-1. An older ROS <c>ur_driver</c> program
/// (ros-industrial/universal_robot a8f1ceb) reads all of them in its I/O publisher thread; the twin refused it at compile time
/// ("unknown function 'get_analog_out'"), and its reads of 8-9 and 2-3 were runtime errors.
/// </summary>
public sealed class ThirdPartyUrDeprecatedIoTests
{
    [Fact]
    public void DeprecatedGetters_ReadTheStandardSignals_ThenTheTools()
    {
        using var twin = new UrTwinController();
        twin.Io.SetBit(UrIoBanks.StandardIn, 3, true);
        twin.Io.SetBit(UrIoBanks.ToolIn, 1, true);
        twin.Io.SetNumber(UrIoBanks.ToolAnalogIn, 0, 0.7);
        UrProgramState state = twin.Run("""
            def io():
              set_tool_digital_out(0, True)
              set_standard_analog_out(1, 0.25)
              textmsg("in ", [get_digital_in(3), get_digital_in(8), get_digital_in(9)])
              textmsg("out ", [get_digital_out(0), get_digital_out(8), get_digital_out(9)])
              textmsg("analog ", [get_analog_in(0), get_analog_in(2), get_analog_out(1)])
            end
            """, CancellationToken.None);
        Assert.True(state == UrProgramState.Finished, twin.Error);

        Assert.Equal(["in [True, False, True]", "out [False, True, False]", "analog [0, 0.7, 0.25]"],
            twin.Pendant.Lines.Where(l => l.StartsWith("in ", StringComparison.Ordinal) || l.StartsWith("out ", StringComparison.Ordinal) || l.StartsWith("analog ", StringComparison.Ordinal)));
    }

    [Theory]
    [InlineData("x = get_digital_in(10)", "get_digital_in: there is no signal 10 (0 to 9)")]
    [InlineData("x = get_analog_in(4)", "get_analog_in: there is no signal 4 (0 to 3)")]
    [InlineData("x = get_analog_out(2)", "get_analog_out: there is no signal 2 (0 to 1)")]
    public void ANumberPastTheTools_StopsTheProgram(string statement, string message)
    {
        using var twin = new UrTwinController();
        UrProgramState state = twin.Run($"def bad():\n  {statement}\nend\n", CancellationToken.None);
        Assert.NotEqual(UrProgramState.Finished, state);
        Assert.Contains(message, twin.Error);
    }
}
