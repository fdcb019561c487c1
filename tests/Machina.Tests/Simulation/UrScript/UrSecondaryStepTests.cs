using Machina.Simulation.UrScript;
using Machina.Tests.Support;

namespace Machina.Tests.Simulation.UrScript;

/// <summary>
/// A secondary program runs in one controller step (the Script Manual: it "must be simple enough to be executed in a single
/// controller step, without blocking the realtime thread"; "Secondary Program Limitations": "Entire execution time is added to
/// single real time cycle", more gives "Runtime is too much behind"). The twin used to run a looping secondary program beside
/// the main program for as long as it looped (an endless one for ever, a core busy). Now one that does more than its step's
/// work stops there with that error in the controller's log and a protective stop; a short loop still runs to its end.
/// </summary>
public sealed class UrSecondaryStepTests
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

    [Theory]
    [InlineData("while True:\n    i = i + 1\n  end")]
    [InlineData("while True:\n  end")] // an empty loop: its turns count, no statement runs
    [InlineData("while i < 1000000:\n    i = i + 1\n  end")]
    public void ASecProgram_LoopingPastOneControllerStep_StopsThere_TooMuchBehind_WithAProtectiveStop(string loop)
    {
        var clock = new ManualClock();
        using var twin = new UrTwinController(new UrTwinOptions { Time = clock, RealTime = true });
        Assert.True(twin.Start(Main), twin.Error);
        Assert.True(SpinWait.SpinUntil(() => twin.Pendant.Lines.Contains("main started"), Bound), "the main program did not start");

        twin.Receive($"sec spinning():\n  i = 0\n  write_output_integer_register(3, 1)\n  {loop}\n  write_output_integer_register(3, 2)\nend\n");
        Assert.True(SpinWait.SpinUntil(() => twin.SecondaryProgramsRun == 1, Bound), $"the secondary program did not end: {twin.Error}");

        string error = Assert.Single(twin.SecondaryErrors);
        Assert.StartsWith("Secondary program: Runtime error: line ", error);
        Assert.Contains(": Runtime is too much behind", error);
        Assert.Equal(1, twin.Io.GetNumber(UrIoBanks.OutputIntRegisters, 3)); // what it did before stays; it went no further
        Assert.Contains("Protective stop: Runtime is too much behind", twin.Pendant.Lines);
        Assert.True(twin.IsHeld); // the controller missed its cycle: the arm is stopped and the main program held
        Assert.Equal(UrProgramState.Running, twin.State);
    }

    [Fact]
    public void ASecProgram_WithAShortLoop_RunsToItsEnd()
    {
        var clock = new ManualClock();
        using var twin = new UrTwinController(new UrTwinOptions { Time = clock, RealTime = true });
        Assert.True(twin.Start(Main), twin.Error);
        Assert.True(SpinWait.SpinUntil(() => twin.Pendant.Lines.Contains("main started"), Bound), "the main program did not start");

        twin.Receive("sec counting():\n  i = 0\n  while i < 100:\n    set_standard_digital_out(i % 8, i % 2 == 0)\n    i = i + 1\n  end\n  write_output_integer_register(3, i)\nend\n");
        Assert.True(SpinWait.SpinUntil(() => twin.SecondaryProgramsRun == 1, Bound), $"the secondary program did not end: {twin.Error}");

        Assert.Empty(twin.SecondaryErrors);
        Assert.Equal(100, twin.Io.GetNumber(UrIoBanks.OutputIntRegisters, 3));
        Assert.False(twin.IsHeld);
        Assert.Equal(UrProgramState.Running, twin.State);
    }
}
