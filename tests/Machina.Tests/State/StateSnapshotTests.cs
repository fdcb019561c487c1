namespace Machina.Tests.State;

/// <summary>State snapshots cannot be changed by user code, not even by casting their maps back to dictionaries.</summary>
public class StateSnapshotTests
{
    [Fact]
    public void Maps_CannotBeChangedThroughACast()
    {
        var bot = Robot.Create("Bot", RobotType.ABB);
        RobotState empty = bot.GetCurrentState();
        bot.WriteDigital(1, true);
        bot.WriteAnalog(2, 0.5);
        bot.DefineTool("pen", new Vector(0, 0, 10), Rotation.Identity);
        RobotState full = bot.GetCurrentState();

        foreach (RobotState s in new[] { empty, full })
        {
            Assert.Throws<NotSupportedException>(() => ((IDictionary<string, bool>)s.DigitalOutputs)["9"] = true);
            Assert.Throws<NotSupportedException>(() => ((IDictionary<string, double>)s.AnalogOutputs)["9"] = 1);
            Assert.Throws<NotSupportedException>(() => ((IDictionary<string, Tool>)s.DefinedTools).Clear());
        }
        Assert.Empty(Robot.Create("Other", RobotType.ABB).GetCurrentState().DigitalOutputs);
        Assert.True(full.DigitalOutputs["1"]);
        Assert.Equal(0.5, full.AnalogOutputs["2"]);
        Assert.Equal("pen", full.DefinedTools["pen"].Name);
    }
}
