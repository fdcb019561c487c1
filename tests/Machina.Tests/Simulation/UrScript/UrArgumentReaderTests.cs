using Machina.Simulation.UrScript;

namespace Machina.Tests.Simulation.UrScript;

/// <summary>
/// The built-ins read their arguments without naming them first (the name is built only for the error): a wrong type still stops the
/// program with the argument named, for each kind of reader (number, integer, bool, string, pose).
/// </summary>
public class UrArgumentReaderTests
{
    [Theory]
    [InlineData("movel(p[0.3, -0.1, 0.4, 0, 3.14, 0], a=\"fast\")", "movel: argument 'a' must be a number, not string")]
    [InlineData("sleep(p[0, 0, 0, 0, 0, 0])", "sleep: argument 't' must be a number, not pose")]
    [InlineData("x = socket_read_binary_integer(2.5)", "socket_read_binary_integer: argument 'number' must be an integer, not 2.5")]
    [InlineData("x = socket_read_binary_integer(\"2\")", "socket_read_binary_integer: argument 'number' must be an integer, not string")]
    [InlineData("set_standard_digital_out(1, \"on\")", "set_standard_digital_out: argument 'b' must be a bool, not string")]
    [InlineData("socket_send_int(1, 5)", "socket_send_int: argument 'socket_name' must be a string, not int")]
    public void AWrongType_StopsTheProgram_NamingTheArgument(string call, string reason)
    {
        using var twin = new UrTwinController();
        Assert.Equal(UrProgramState.Failed, twin.Run($"def prog():\n  {call}\nend\n", CancellationToken.None));
        Assert.Equal("Runtime error: line 2: " + reason, twin.Error);
    }

    [Fact]
    public void RightTypes_AreRead_IntsAsNumbersAndFloatsAsWholeIntegers()
    {
        using var twin = new UrTwinController();
        UrProgramState state = twin.Run("""
            def prog():
              set_standard_digital_out(2, 1)
              set_standard_digital_out(3, True)
              write_output_integer_register(4.0, 7)
              sleep(1)
              textmsg(get_standard_digital_out(2), get_standard_digital_out(3))
              textmsg(read_output_integer_register(4))
            end
            """, CancellationToken.None);
        Assert.True(state == UrProgramState.Finished, twin.Error);
        Assert.Equal(["TrueTrue", "7"], twin.Pendant.Lines);
        Assert.Equal(1, twin.Clock.Seconds, 6);
    }
}
