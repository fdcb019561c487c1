using Machina.Simulation.Rapid;

namespace Machina.Tests.Simulation.Rapid;

/// <summary>
/// Session 34 (perf54r, issue 45): a MoveL, MoveJ or MoveC whose tooldata and wobjdata are identical to the last move's takes their
/// frames from that move instead of reading the data again. A component changed in place, a new datum or a MoveAbsJ between them
/// makes the next move read its data again.
/// </summary>
public class RapidMoveFramesTests
{
    [Fact]
    public void AToolOrWorkObjectChangedInPlace_MovesTheFlange_AtTheNextMove()
    {
        var twin = new RapidTwinController(new RapidTwinOptions { Model = RobotModels.Get("IRB 1600-8/1.45") });
        twin.Load(("T.mod",
            """
            MODULE T
            PERS tooldata tool := [TRUE, [[0, 0, 100], [1, 0, 0, 0]], [1, [0, 0, 1], [1, 0, 0, 0], 0, 0, 0]];
            PERS wobjdata wobj := [FALSE, TRUE, "", [[10, 0, 0], [1, 0, 0, 0]], [[0, 0, 0], [1, 0, 0, 0]]];
            VAR robtarget p := [[303, 0, 558], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
            PROC main()
              MoveL p, v100, fine, tool \WObj:=wobj;
              Flange "first";
              MoveL p, v100, fine, tool \WObj:=wobj;
              Flange "same";
              tool.tframe.trans.z := 200;
              MoveL p, v100, fine, tool \WObj:=wobj;
              Flange "tool";
              wobj.oframe.trans.x := 5;
              MoveL p, v100, fine, tool \WObj:=wobj;
              Flange "wobj";
              MoveJ p, v100, fine, tool;
              Flange "no wobj";
              MoveAbsJ CJointT(), v100, fine, tool0;
              tool.tframe.trans.z := 50;
              MoveL p, v100, fine, tool \WObj:=wobj;
              Flange "after absj";
            ENDPROC
            PROC Flange(string label)
              VAR robtarget f;
              f := CRobT(\Tool:=tool0 \WObj:=wobj0);
              TPWrite label + " " + NumToStr(f.trans.x, 1) + " " + NumToStr(f.trans.z, 1) + " " + NumToStr(CTool().tframe.trans.z, 0);
            ENDPROC
            ENDMODULE
            """));
        Assert.True(twin.Run() == RapidProgramState.Finished, twin.Error);

        Assert.Equal(["first 313 658 100", "same 313 658 100", "tool 313 758 200", "wobj 318 758 200", "no wobj 303 758 200",
            "after absj 318 608 50"], twin.Pendant.Lines);
    }
}
