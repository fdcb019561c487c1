using Machina.Simulation.Rapid;
using Machina.Tests.Support;

namespace Machina.Tests.Simulation.Rapid;

/// <summary>
/// A RAPID <c>clock</c> (ClkStart, ClkRead) counts the time that passes, whichever task reads it and whatever it waits for. The
/// twin counted only the motion task's program time (its moves and waits), so a background task's clock stood still in real
/// time: yumipy's <c>joints_logger</c> (BerkeleyAutomation/yumipy, a task beside the YuMi's servers) stamped every report 0.
/// </summary>
public sealed class ThirdPartyRapidClockTests
{
    private static readonly TimeSpan Bound = TimeSpan.FromMinutes(1);

    [Fact]
    public void ABackgroundTasksClock_CountsItsWaitInRealTime()
    {
        var clock = new ManualClock();
        var twin = new RapidTwinController(new RapidTwinOptions { Time = clock, RealTime = true });
        twin.Task("T_LOG").Load([("log.mod", """
            MODULE log
              VAR clock timer;
              PROC main()
                ClkStart timer;
                WaitTime 0.5;
                TPWrite "logged " \Num:=ClkRead(timer);
              ENDPROC
            ENDMODULE
            """)]);
        twin.StartTasks();
        try
        {
            Assert.True(SpinWait.SpinUntil(() => clock.PendingTimers == 1, Bound), "the WaitTime did not start");
            clock.Advance(TimeSpan.FromSeconds(0.5));
            Assert.True(SpinWait.SpinUntil(() => twin.Pendant.Lines.Any(l => l.Contains("logged", StringComparison.Ordinal)), Bound),
                $"the task did not go on: {twin.Task("T_LOG").State}");
            Assert.Contains(twin.Pendant.Lines, l => l.EndsWith("logged 0.5", StringComparison.Ordinal));
        }
        finally
        {
            twin.StopTasks(TimeSpan.FromSeconds(10));
        }
    }

    [Fact]
    public void AClock_WithoutRealTime_CountsProgramTime()
    {
        var twin = new RapidTwinController();
        twin.Load([("T.mod", """
            MODULE T
              VAR clock timer;
              PROC main()
                ClkStart timer;
                WaitTime 1.5;
                ClkStop timer;
                WaitTime 1;
                TPWrite "counted " \Num:=ClkRead(timer);
              ENDPROC
            ENDMODULE
            """)]);
        Assert.Equal(RapidProgramState.Finished, twin.Run());
        Assert.Equal(["counted 1.5"], twin.Pendant.Lines);
    }
}
