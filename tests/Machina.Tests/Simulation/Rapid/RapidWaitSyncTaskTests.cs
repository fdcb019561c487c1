using Machina.Simulation.Rapid;

namespace Machina.Tests.Simulation.Rapid;

/// <summary>WaitSyncTask between loaded tasks (Multitasking), as a cell's robot and PLC tasks meet at the start of each cycle.</summary>
public class RapidWaitSyncTaskTests
{
    private const string Shared = """
          PERS tasks both{2} := [["T_ROB1"], ["T_PLC"]];
          PERS num prepared := 0;
          VAR syncident cycleStart;
        """;

    [Fact]
    public void EachTask_WaitsAtTheSyncPoint_UntilTheOtherReachedItToo()
    {
        var twin = new RapidTwinController();
        twin.Task("T_ROB1").Load([("Rob.mod", $$"""
            MODULE Rob
            {{Shared}}
              PROC main()
                WaitSyncTask \InPos, cycleStart, both;
                TPWrite "robot passed, prepared " \Num:=prepared;
                WaitSyncTask cycleStart, both;
                TPWrite "robot passed again, prepared " \Num:=prepared;
              ENDPROC
            ENDMODULE
            """)]);
        twin.Task("T_PLC").Load([("Plc.mod", $$"""
            MODULE Plc
            {{Shared}}
              PROC main()
                WaitTime 0.3;
                prepared := 1;
                WaitSyncTask cycleStart, both;
                WaitTime 0.3;
                prepared := 2;
                WaitSyncTask cycleStart, both;
              ENDPROC
            ENDMODULE
            """)]);
        RapidTaskRuns.RunToEnd(twin, 20);

        Assert.Equal(RapidProgramState.Finished, twin.Task("T_ROB1").State);
        Assert.Equal(RapidProgramState.Finished, twin.Task("T_PLC").State);
        Assert.Equal(["robot passed, prepared 1", "robot passed again, prepared 2"], twin.Pendant.Lines);
    }

    [Fact]
    public void ATaskThatNeverComes_EndsTheWaitWithErrWaitsynctaskAfterTimeOut_AndAnUnloadedTaskIsRefused()
    {
        var twin = new RapidTwinController();
        twin.Task("T_PLC").Load([("Plc.mod", "MODULE Plc\nPROC main()\nENDPROC\nENDMODULE\n")]);
        twin.Task("T_ROB1").Load([("Rob.mod", $$"""
            MODULE Rob
            {{Shared}}
              PERS tasks other{2} := [["T_ROB1"], ["T_ROB9"]];
              PROC main()
                WaitSyncTask cycleStart, both \TimeOut:=0.2;
                TPWrite "not reached";
                WaitSyncTask cycleStart, other;
                TPWrite "end";
              ERROR
                TPWrite "ERR_WAITSYNCTASK " + ValToStr(ERRNO = ERR_WAITSYNCTASK) + ", ERR_ARGVALERR " + ValToStr(ERRNO = ERR_ARGVALERR);
                TRYNEXT;
              ENDPROC
            ENDMODULE
            """)]);

        Assert.True(twin.Run() == RapidProgramState.Finished, twin.Error);
        Assert.Equal(["ERR_WAITSYNCTASK TRUE, ERR_ARGVALERR FALSE", "not reached", "ERR_WAITSYNCTASK FALSE, ERR_ARGVALERR TRUE", "end"], twin.Pendant.Lines);
    }
}
