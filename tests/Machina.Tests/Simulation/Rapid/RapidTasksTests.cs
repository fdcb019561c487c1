using Machina.Simulation.Rapid;

namespace Machina.Tests.Simulation.Rapid;

/// <summary>Tasks of the RAPID twin run at once and share PERS data; a motion error that stops one task runs the error traps of the others.</summary>
public class RapidTasksTests
{
    private const string Motion = """
        MODULE M
          PERS num shared := 0;
          PROC main()
            WaitUntilArmed;
            MoveL [[5000, 0, 400], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]], v100, fine, tool0;
            shared := -1;
          ENDPROC
          PROC WaitUntilArmed()
            WHILE shared = 0 DO
              WaitTime 0.001;
            ENDWHILE
          ENDPROC
        ENDMODULE
        """;

    private const string Watcher = """
        MODULE W
          PERS num shared := 0;
          PERS num reported := 0;
          VAR intnum motionError;
          PROC main()
            IDelete motionError;
            CONNECT motionError WITH OnError;
            IError MOTION_ERR, TYPE_ERR, motionError;
            shared := 1;
            WHILE reported = 0 DO
              WaitTime 0.005;
            ENDWHILE
          ENDPROC
          TRAP OnError
            VAR trapdata data;
            VAR errdomain domain;
            VAR num number;
            VAR errtype kind;
            GetTrapData data;
            ReadErrData data, domain, number, kind;
            reported := domain * 10000 + number + kind / 10;
          ENDTRAP
        ENDMODULE
        """;

    [Fact]
    public void MotionErrorInOneTask_RunsTheErrorTrapOfAnother_WithDomainNumberAndType()
    {
        var twin = new RapidTwinController();
        twin.Task().Load([("M.mod", Motion)]);
        twin.Task("T_WATCH").Load([("W.mod", Watcher)]);

        twin.StartTasks();
        bool joined = twin.StopTasksWhenEnded(TimeSpan.FromSeconds(20));

        Assert.True(joined, "both tasks to end");
        Assert.Equal(RapidProgramState.Failed, twin.Task().State);
        Assert.StartsWith("50050 Position outside reach", twin.Task().Error, StringComparison.Ordinal);
        Assert.Equal(RapidProgramState.Finished, twin.Task("T_WATCH").State);
        // MOTION_ERR is domain 5, the event 50050 is its number 50, TYPE_ERR is 3.
        Assert.Equal(50050.3, (double)twin.Persistents["reported"].Value, 9);
        Assert.Equal(1.0, (double)twin.Persistents["shared"].Value);
    }

    [Fact]
    public void IError_WithoutConnect_StopsTheTaskWithItsLine()
    {
        var twin = new RapidTwinController();
        twin.Load(("T.mod", "MODULE T\n  VAR intnum i;\n  PROC main()\n    IError MOTION_ERR, TYPE_ERR, i;\n  ENDPROC\nENDMODULE"));

        Assert.Equal(RapidProgramState.Failed, twin.Run());
        Assert.Equal("Execution error: line 4: IError: the interrupt is not connected to a trap (CONNECT it first) (task T_ROB1)", twin.Error);
    }

    /// <summary>
    /// A stopped task runs no further statement, even one that does not wait (a stop reached it between two instructions): the
    /// task that a restart stopped once accepted a client and greeted it with its old progress (the ABB restart trial).
    /// </summary>
    [Fact]
    public void StoppedTask_RunsNoFurtherStatement()
    {
        var twin = new RapidTwinController();
        twin.Load(("T.mod", "MODULE T\n  VAR num n := 0;\n  PROC main()\n    n := 1;\n    TPWrite \"ran\";\n  ENDPROC\nENDMODULE\n"));
        using var stopped = new CancellationTokenSource();
        stopped.Cancel();

        Assert.Equal(RapidProgramState.Stopped, twin.Run("main", stopped.Token));
        Assert.Empty(twin.Pendant.Lines);
    }
}
