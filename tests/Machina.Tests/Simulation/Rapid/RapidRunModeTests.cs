using Machina.Simulation.Rapid;

namespace Machina.Tests.Simulation.Rapid;

/// <summary>
/// The controller's run mode and task types (issue 42): a static or semistatic task runs its main for ever, a normal task once in
/// single-cycle mode and again and again in continuous mode, with its data kept between cycles; an error stops any of them.
/// </summary>
public class RapidRunModeTests
{
    private static readonly TimeSpan Limit = TimeSpan.FromSeconds(20);

    /// <summary>A background main that counts its cycles in a VAR (kept between cycles) and shows the count in a PERS.</summary>
    private const string Counter = """
        MODULE C
          PERS num cycles := 0;
          VAR num runs := 0;
          PROC main()
            Incr runs;
            cycles := runs;
            WaitTime 0.001;
          ENDPROC
        ENDMODULE
        """;

    /// <summary>The motion task waits until the background main ran three times.</summary>
    private const string Waiter = """
        MODULE W
          PERS num cycles := 0;
          PROC main()
            WHILE cycles < 3 DO
              WaitTime 0.001;
            ENDWHILE
            TPWrite "seen three cycles";
          ENDPROC
        ENDMODULE
        """;

    /// <summary>A main that writes its cycle and ends the program with EXIT at the third (RwsRunModeTests runs it too).</summary>
    internal const string ThreeCycles = """
        MODULE T
          VAR num runs := 0;
          PROC main()
            Incr runs;
            TPWrite "cycle " \Num:=runs;
            IF runs >= 3 EXIT;
          ENDPROC
        ENDMODULE
        """;

    [Theory]
    [InlineData("SEMISTATIC")]
    [InlineData("STATIC")]
    public void BackgroundTaskOfAStaticType_StartsMainAgainWhenItEnds_DataKept_AndRunsOnAfterTheNormalTask(string typeName)
    {
        RapidTaskType type = typeName == "STATIC" ? RapidTaskType.Static : RapidTaskType.SemiStatic;
        var twin = new RapidTwinController();
        twin.Task().Load([("W.mod", Waiter)]);
        twin.Task("T_BG").Load([("C.mod", Counter)]);
        twin.Task("T_BG").Type = type;

        twin.StartTasks();
        try
        {
            Assert.True(SpinWait.SpinUntil(() => twin.Task().State != RapidProgramState.Running, Limit), "the motion task to see three cycles");
            Assert.Equal(RapidProgramState.Finished, twin.Task().State);
            Assert.Equal("seen three cycles", twin.Pendant.Lines.Single());
            // The normal task ended; the background task runs on (its cycles go on counting).
            double seen = (double)twin.Task("T_BG").Program.Globals["cycles"].Value;
            Assert.True(SpinWait.SpinUntil(() => (double)twin.Task("T_BG").Program.Globals["cycles"].Value > seen, Limit), "more cycles");
            Assert.Equal(RapidProgramState.Running, twin.Task("T_BG").State);
            Assert.False(twin.IsRunning); // the execution state is the normal tasks'
        }
        finally
        {
            Assert.True(twin.StopTasks(TimeSpan.FromSeconds(10)));
        }
        Assert.Equal(RapidProgramState.Stopped, twin.Task("T_BG").State);
    }

    [Fact]
    public void NormalBackgroundTask_InSingleCycleMode_RunsMainOnce()
    {
        var twin = new RapidTwinController();
        twin.Task("T_BG").Load([("C.mod", Counter)]);

        RapidTaskRuns.RunToEnd(twin, Limit.TotalSeconds);

        Assert.Equal(RapidExecutionCycle.Once, twin.Cycle);
        Assert.Equal(RapidProgramState.Finished, twin.Task("T_BG").State);
        Assert.Equal(1.0, twin.Task("T_BG").Program.Globals["cycles"].Value);
    }

    [Fact]
    public void NormalTask_InContinuousMode_StartsMainAgain_UntilExit()
    {
        var twin = new RapidTwinController { Cycle = RapidExecutionCycle.Forever };
        twin.Load(("T.mod", ThreeCycles));

        Assert.Equal(RapidProgramState.Finished, twin.Run());

        Assert.Equal(["cycle 1", "cycle 2", "cycle 3"], twin.Pendant.Lines);
    }

    [Fact]
    public void NormalTask_InSingleCycleMode_RunsMainOnce()
    {
        var twin = new RapidTwinController();
        twin.Load(("T.mod", ThreeCycles));

        Assert.Equal(RapidProgramState.Finished, twin.Run());

        Assert.Equal(["cycle 1"], twin.Pendant.Lines);
    }

    [Fact]
    public void SemiStaticTask_StoppedByAnError_IsNotStartedAgain()
    {
        var twin = new RapidTwinController();
        twin.Task("T_BG").Load([("E.mod", """
            MODULE E
              VAR num runs := 0;
              VAR num zero := 0;
              PROC main()
                Incr runs;
                TPWrite "cycle " \Num:=runs;
                IF runs = 2 runs := runs / zero;
              ENDPROC
            ENDMODULE
            """)]);
        twin.Task("T_BG").Type = RapidTaskType.SemiStatic;

        RapidTaskRuns.RunToEnd(twin, Limit.TotalSeconds);

        Assert.Equal(RapidProgramState.Failed, twin.Task("T_BG").State);
        Assert.Equal(["cycle 1", "cycle 2"], twin.Pendant.Lines.Take(2));
        Assert.DoesNotContain("cycle 3", twin.Pendant.Lines);
    }
}
