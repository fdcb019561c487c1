using Machina.Simulation.UrScript;

namespace Machina.Tests.Simulation.UrScript;

/// <summary>
/// <c>set_flag(n, b)</c> and <c>get_flag(n)</c> (Script Manual, module interfaces: flags behave like internal digital outputs
/// and keep their information between program runs; n is 0 to 32). The ROS <c>ur_driver</c> program (ros-industrial/universal_robot,
/// <c>ur_driver/prog</c>, which ran on CB2/CB3 controllers) sets them on its client's request; the twin refused that program
/// with "unknown function 'set_flag'" before it ran a line.
/// </summary>
public sealed class ThirdPartyUrFlagTests
{
    [Fact]
    public void Flags_SetInOneProgram_AreReadByTheNext()
    {
        using var twin = new UrTwinController();
        UrProgramState first = twin.Run("""
            def setFlags():
              set_flag(0, True)
              set_flag(32, True)
              set_flag(5, True)
              set_flag(5, False)
              textmsg("in run 0=", get_flag(0))
              textmsg("in run 5=", get_flag(5))
            end
            """, CancellationToken.None);
        Assert.True(first == UrProgramState.Finished, twin.Error);

        UrProgramState second = twin.Run("""
            def readFlags():
              textmsg("next run 0=", get_flag(0))
              textmsg("next run 1=", get_flag(1))
              textmsg("next run 5=", get_flag(5))
              textmsg("next run 32=", get_flag(32))
            end
            """, CancellationToken.None);
        Assert.True(second == UrProgramState.Finished, twin.Error);

        Assert.Equal(["in run 0=True", "in run 5=False", "next run 0=True", "next run 1=False", "next run 5=False", "next run 32=True"],
            twin.Pendant.Lines.Where(l => l.Contains(" run ", StringComparison.Ordinal)));
    }

    [Theory]
    [InlineData("set_flag(33, True)", "set_flag: there is no signal 33 (0 to 32)")]
    [InlineData("x = get_flag(-1)", "get_flag: there is no signal -1 (0 to 32)")]
    public void AFlagOutside0To32_StopsTheProgram(string statement, string message)
    {
        using var twin = new UrTwinController();
        UrProgramState state = twin.Run($"def bad():\n  {statement}\nend\n", CancellationToken.None);
        Assert.NotEqual(UrProgramState.Finished, state);
        Assert.Contains(message, twin.Error);
    }
}
