using Machina.Simulation.Rapid;

namespace Machina.Tests.Simulation.Rapid;

/// <summary>
/// Timer and signal interrupts (issue 42): ITimer, ISignalDI, ISignalDO with \Single, ISleep/IWatch, IDisable/IEnable, a trap that
/// runs while the task waits, and a signal changed from outside (a sensor, RWS, the command line) while the program runs.
/// </summary>
public class RapidEventInterruptTests
{
    private static readonly (string, string)[] Signals = [("do1", "signaldo"), ("di1", "signaldi")];

    private static RapidTwinController Run(string body, string data)
    {
        var twin = new RapidTwinController(new RapidTwinOptions { Signals = Signals });
        twin.Load(("T.mod", $"MODULE T\n{data}\nPROC main()\n{body}\nENDPROC\nENDMODULE\n"));
        RapidProgramState state = twin.Run();
        Assert.True(state == RapidProgramState.Finished, $"{state}: {twin.Error}");
        return twin;
    }

    [Fact]
    public void ITimer_InterruptsAWaitTime_EveryPeriodOfProgramTime_AndSingleOnlyOnce()
    {
        RapidTwinController twin = Run(
            """
              CONNECT every WITH TTick;
              CONNECT once WITH TOnce;
              ITimer 0.25, every;
              ITimer \Single, 0.5, once;
              WaitTime 1.1;
              IDelete every;
              WaitTime 1;
              TPWrite "ticks " \Num:=ticks;
              TPWrite "time " \Num:=ClkRead(clock1);
            """,
            """
            VAR intnum every;
            VAR intnum once;
            VAR num ticks := 0;
            TRAP TTick
              ticks := ticks + 1;
              IF ticks = 1 ClkStart clock1;
            ENDTRAP
            TRAP TOnce
              TPWrite "once at tick " \Num:=ticks;
            ENDTRAP
            """);

        // Due at 0.25, 0.5, 0.75 and 1.0 s of the 1.1 s wait; the single timer once, after the second tick (both due at 0.5 s).
        Assert.Equal(["once at tick 2", "ticks 4", "time 1.85"], twin.Pendant.Lines);
    }

    [Fact]
    public void ISignalDO_QueuesItsTrap_OnTheChangeToItsValue_SleepDropsAndSingleEnds()
    {
        RapidTwinController twin = Run(
            """
              CONNECT up WITH TUp;
              CONNECT any WITH TAny;
              ISignalDO do1, 1, up;
              ISignalDO \Single, do1, edge, any;
              SetDO do1, 1;
              TPWrite "after set";
              SetDO do1, 0;
              ISleep up;
              SetDO do1, 1;
              SetDO do1, 0;
              IWatch up;
              Set do1;
              Set do1;
              TPWrite "ups " \Num:=ups;
            """,
            """
            VAR intnum up;
            VAR intnum any;
            VAR num ups := 0;
            TRAP TUp
              ups := ups + 1;
              TPWrite "up " \Num:=DOutput(do1);
            ENDTRAP
            TRAP TAny
              TPWrite "edge once";
            ENDTRAP
            """);

        // The trap runs before the statement after SetDO; asleep, the change is dropped; setting a 1 that is already 1 changes nothing.
        Assert.Equal(["up 1", "edge once", "after set", "up 1", "ups 2"], twin.Pendant.Lines);
    }

    [Fact]
    public void IDisable_HoldsTheTrapsUntilIEnable()
    {
        RapidTwinController twin = Run(
            """
              CONNECT up WITH TUp;
              ISignalDO do1, 1, up;
              IDisable;
              SetDO do1, 1;
              TPWrite "disabled";
              IEnable;
              TPWrite "enabled";
            """,
            """
            VAR intnum up;
            TRAP TUp
              TPWrite "trap";
            ENDTRAP
            """);

        Assert.Equal(["disabled", "trap", "enabled"], twin.Pendant.Lines);
    }

    [Fact]
    public void ISignalDI_AnInputSetFromOutside_RunsTheTrapWhileTheTaskWaits()
    {
        var twin = new RapidTwinController(new RapidTwinOptions { Signals = Signals, RealTime = true });
        twin.Load(("T.mod", """
            MODULE T
            VAR intnum sensor;
            VAR bool seen := FALSE;
            PROC main()
              CONNECT sensor WITH TSensor;
              ISignalDI di1, high, sensor;
              TPWrite "waiting";
              WaitUntil seen \MaxTime:=20;
              TPWrite "seen " \Num:=DInput(di1);
            ENDPROC
            TRAP TSensor
              seen := TRUE;
            ENDTRAP
            ENDMODULE
            """));
        twin.StartTasks();
        try
        {
            for (int i = 0; i < 2000 && !twin.Pendant.Lines.Contains("waiting"); i++)
            {
                Thread.Sleep(5);
            }
            Assert.True(twin.SetSignal("di1", 1));
            Assert.True(twin.StopTasksWhenEnded(TimeSpan.FromSeconds(20)));
        }
        finally
        {
            twin.StopTasks(TimeSpan.FromSeconds(10));
        }

        Assert.Equal(RapidProgramState.Finished, twin.Task().State);
        Assert.Equal(["waiting", "seen 1"], twin.Pendant.Lines);
    }

    [Fact]
    public void ITimer_ShorterThanTheManualAllows_IsRefusedAtRunTime()
    {
        var twin = new RapidTwinController();
        twin.Load(("T.mod", "MODULE T\nVAR intnum t;\nPROC main()\nCONNECT t WITH Tr;\nITimer 0.05, t;\nENDPROC\nTRAP Tr\nENDTRAP\nENDMODULE\n"));

        Assert.Equal(RapidProgramState.Failed, twin.Run());
        Assert.StartsWith("Execution error: line 5: ITimer: the time 0.05 s is below 0.1 s (the least for a cyclic timer)", twin.Error, StringComparison.Ordinal);
    }
}
