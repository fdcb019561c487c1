using Machina.Simulation.UrScript;
using Machina.Tests.Support;

namespace Machina.Tests.Simulation.UrScript;

/// <summary>
/// Secondary programs (the Script Manual's "Secondary Programs"): a <c>sec</c> program sent to a script port runs beside the
/// main program, which goes on; it cannot use physical time (no motion, no sleep); its errors do not stop the main program and
/// go to the controller's log, not the pendant. The twin used to refuse <c>sec</c> as a compile error.
/// </summary>
public sealed class UrSecondaryProgramTests
{
    private static readonly TimeSpan Bound = TimeSpan.FromMinutes(1);

    private const string Main = """
        def main():
          textmsg("main started")
          while True:
            sleep(1)
          end
        end
        """;

    [Fact]
    public void ASecProgram_RunsBesideTheMainProgram_WhichGoesOn()
    {
        var clock = new ManualClock();
        using var twin = new UrTwinController(new UrTwinOptions { Time = clock, RealTime = true });
        Assert.True(twin.Start(Main), twin.Error);
        Assert.True(SpinWait.SpinUntil(() => twin.Pendant.Lines.Contains("main started") && clock.PendingTimers == 1, Bound), "the main program did not start");

        twin.Receive("sec secondaryProgram():\n  set_standard_digital_out(1, True)\n  write_output_integer_register(3, 42)\nend\n");
        Assert.True(SpinWait.SpinUntil(() => twin.SecondaryProgramsRun == 1, Bound), $"the secondary program did not run: {twin.Error}");

        Assert.True(twin.Io.GetBit(UrIoBanks.StandardOut, 1));
        Assert.Equal(42, twin.Io.GetNumber(UrIoBanks.OutputIntRegisters, 3));
        Assert.Equal(UrProgramState.Running, twin.State); // the main program was not replaced
        Assert.Equal(1, twin.ProgramsStarted);
        Assert.Equal("main", twin.ProgramName);
        Assert.Empty(twin.SecondaryErrors);
    }

    [Theory]
    [InlineData("movej([0, -1.57, 1.57, -1.57, -1.57, 0])", "movej")]
    [InlineData("sleep(0.1)", "sleep")]
    public void ASecProgram_ThatUsesPhysicalTime_IsRefused_AndTheMainProgramGoesOn(string statement, string function)
    {
        var clock = new ManualClock();
        using var twin = new UrTwinController(new UrTwinOptions { Time = clock, RealTime = true });
        Joints start = twin.Arm.Joints;
        Assert.True(twin.Start(Main), twin.Error);
        Assert.True(SpinWait.SpinUntil(() => twin.Pendant.Lines.Contains("main started"), Bound), "the main program did not start");

        twin.Receive($"sec moving():\n  set_standard_digital_out(2, True)\n  {statement}\nend\n");
        Assert.True(SpinWait.SpinUntil(() => twin.SecondaryProgramsRun == 1, Bound), "the secondary program was not taken");

        string error = Assert.Single(twin.SecondaryErrors);
        Assert.Contains($"line 3: {function}: a secondary program cannot use physical time", error);
        Assert.False(twin.Io.GetBit(UrIoBanks.StandardOut, 2)); // refused whole: nothing of it ran
        Assert.Equal(start, twin.Arm.Joints);
        Assert.Equal(UrProgramState.Running, twin.State);
    }

    [Fact]
    public void ASecProgramsRuntimeError_GoesToTheLog_NotThePendant_AndTheMainProgramGoesOn()
    {
        var clock = new ManualClock();
        using var twin = new UrTwinController(new UrTwinOptions { Time = clock, RealTime = true });
        Assert.True(twin.Start(Main), twin.Error);
        Assert.True(SpinWait.SpinUntil(() => twin.Pendant.Lines.Contains("main started"), Bound), "the main program did not start");

        twin.Receive("sec failing():\n  x = [1, 2]\n  y = x[5]\nend\n");
        Assert.True(SpinWait.SpinUntil(() => twin.SecondaryProgramsRun == 1, Bound), "the secondary program did not run");

        string error = Assert.Single(twin.SecondaryErrors);
        Assert.StartsWith("Secondary program: Runtime error: line 3:", error);
        Assert.DoesNotContain(twin.Pendant.Lines, l => l.Contains("line 3", StringComparison.Ordinal));
        Assert.Equal(UrProgramState.Running, twin.State);
        Assert.Null(twin.Error);
    }
}
