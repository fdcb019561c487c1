using Machina.Simulation.Rapid;
using Machina.Simulation.Twin;

namespace Machina.Tests.Simulation.Rapid;

/// <summary>
/// StorePath and RestoPath (a trap or error handler that moves while the program's motion is stopped), and ContactL, in programs of
/// our own written as published RobotStudio examples and YuMi servers use them.
/// </summary>
public class RapidPathLevelTests
{
    [Fact]
    public void ATrapThatMovesDuringAMotion_StoresThePath_MovesOnItsOwnLevel_AndTheClearedMotionStaysCleared()
    {
        var twin = new RapidTwinController(new RapidTwinOptions { RealTime = true });
        twin.Task("T_ROB1").Load([("Task1.mod", """
            MODULE Task1
              PERS bool flag := FALSE;
              VAR intnum changed;
              CONST jointtarget jA := [[20, 0, 0, 0, 90, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
              CONST jointtarget jC := [[0, 10, 0, 0, 90, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
              CONST jointtarget jD := [[0, -10, 0, 0, 90, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
              VAR jointtarget now;
              PROC main()
                CONNECT changed WITH Moved;
                IPers flag, changed;
                MoveAbsJ jA, v100 \T:=30, fine, tool0;
                now := CJointT();
                TPWrite "after the cleared move j1 " + NumToStr(now.robax.rax_1, 1) + " j2 " + NumToStr(now.robax.rax_2, 1);
              ENDPROC
              TRAP Moved
                StopMove;
                ClearPath;
                StorePath;
                MoveAbsJ jC, v100 \T:=0.2, fine, tool0;
                MoveAbsJ jD, v100 \T:=0.2, fine, tool0;
                RestoPath;
                StartMove;
                TPWrite "trap done";
              ENDTRAP
            ENDMODULE
            """)]);
        twin.Task("T2").Load([("Task2.mod", """
            MODULE Task2
              PERS bool flag := FALSE;
              PROC main()
                WaitTime 0.3;
                flag := TRUE;
              ENDPROC
            ENDMODULE
            """)]);
        RapidTaskRuns.RunToEnd(twin, 25);

        Assert.True(twin.Task().State == RapidProgramState.Finished, twin.Task().Error);
        // The trap's moves ran while the main motion was stopped; its cleared rest was not run after StartMove: the arm stands at jD.
        Assert.Equal(["trap done", "after the cleared move j1 0 j2 -10"], twin.Pendant.Lines);
        Assert.Contains(twin.Arm.Trace, e => e.Kind == TwinTraceKind.Motion && e.Text.EndsWith("(path cleared)", StringComparison.Ordinal));
    }

    [Fact]
    public void RestoPathWithoutStorePath_AndStorePathTwice_AreTheProgramsErrors()
    {
        IReadOnlyList<string> lines = RapidTaskRuns.ArgumentErrors("", "    RestoPath;\n    StorePath;\n    StorePath;\n    TPWrite \"end\";");

        Assert.Equal(["ERR_ARGVALERR TRUE", "ERR_ARGVALERR TRUE", "end"], lines);
    }

    [Fact]
    public void ContactL_WithOrWithoutAZone_MovesStraightToItsTarget_AsAMoveL()
    {
        var twin = new RapidTwinController(new RapidTwinOptions { Acceleration = 1.2 });
        Pose start = twin.Arm.Tcp;
        twin.Load(("T.mod", """
            MODULE T
              CONST speeddata s250 := [250, 500, 5000, 1000];
              VAR robtarget p;
              PROC main()
                p := CRobT(\Tool:=tool0 \WObj:=wobj0);
                p.trans.x := p.trans.x + 100;
                ContactL \DesiredTorque:=50, p, s250, tool0;
                p.trans.z := p.trans.z - 100;
                ContactL p, s250 \Zone:=z10, tool0 \WObj:=wobj0;
              ENDPROC
            ENDMODULE
            """));

        Assert.True(twin.Run() == RapidProgramState.Finished, twin.Error);
        Assert.Equal(2 * (0.1 / 0.25 + 0.25 / 1.2), twin.Clock.Seconds, 6);
        Assert.InRange((twin.Arm.Tcp.Position - (start.Position + new Vector(100, 0, -100))).Length, 0, 1e-6);
        Assert.Equal(2, twin.Arm.Trace.Count(e => e.Kind == TwinTraceKind.Motion && e.Text == "ContactL"));
    }
}
