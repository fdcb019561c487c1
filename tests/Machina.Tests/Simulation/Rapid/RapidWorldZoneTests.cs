using Machina.Simulation.Rapid;
using Machina.Simulation.Twin;

namespace Machina.Tests.Simulation.Rapid;

/// <summary>
/// World zones (WZSphDef, WZBoxDef, WZCylDef, WZDOSet, WZLimSup) as cell setups define them in a system module: an output that tells
/// whether the TCP is in a zone, and a limit zone the controller refuses to move into.
/// </summary>
public class RapidWorldZoneTests
{
    private const string Program = """
        MODULE T
          VAR shapedata ball;
          VAR shapedata box;
          VAR shapedata column;
          VAR wztemporary home;
          VAR wzstationary wall;
          VAR wzstationary pillar;
          VAR robtarget p0;
          VAR robtarget p;
          VAR pos low;
          VAR pos high;
          PROC main()
            p0 := CRobT(\Tool:=tool0 \WObj:=wobj0);
            WZSphDef \Inside, ball, p0.trans, 30;
            WZDOSet \Temp, home \Inside, ball, DO_1, 1;
            TPWrite "at home DO_1 " \Num:=DOutput(DO_1);
            p := p0;
            p.trans.y := p0.trans.y + 50;
            MoveL p, v100, fine, tool0;
            TPWrite "50 mm away DO_1 " \Num:=DOutput(DO_1);
            low := p0.trans + [-50, 100, -50];
            high := p0.trans + [50, 150, 50];
            WZBoxDef \Inside, box, low, high;
            WZLimSup \Stat, wall, box;
            WZCylDef \Inside, column, p0.trans + [0, -100, -50], 20, 100;
            WZLimSup \Stat, pillar, column;
            p.trans.y := p0.trans.y + 90;
            MoveL p, v100, fine, tool0;
            TPWrite "before the wall";
            p.trans.y := p0.trans.y + 160;
            MoveL p, v100, fine, tool0;
            TPWrite "not reached";
          ENDPROC
        ENDMODULE
        """;

    [Fact]
    public void AnOutputZone_TellsWhereTheTcpIs_AndALimitZoneOnThePath_StopsTheTaskBeforeTheArmMoves()
    {
        var twin = new RapidTwinController(new RapidTwinOptions { Signals = [("DO_1", "signaldo")] });
        Pose start = twin.Arm.Tcp;
        twin.Load(("T.mod", Program));

        Assert.Equal(RapidProgramState.Failed, twin.Run());
        Assert.Equal(["at home DO_1 1", "50 mm away DO_1 0", "before the wall"], twin.Pendant.Lines.Take(3));
        Assert.StartsWith("Execution error: line 31: World zone: the motion would take the TCP into the limit zone activated at line 24 (WZLimSup)", twin.Error);
        // The arm stands where the last allowed motion left it, 90 mm from home: the refused one did not start.
        Assert.InRange((twin.Arm.Tcp.Position - (start.Position + new Vector(0, 90, 0))).Length, 0, 1e-6);
    }

    [Fact]
    public void ALimitZoneActivatedAroundTheTcp_AndAShapeNotDefined_AreRefused()
    {
        IReadOnlyList<string> lines = RapidTaskRuns.ArgumentErrors(
            """
              VAR shapedata ball;
              VAR shapedata never;
              VAR wzstationary zone;
              VAR robtarget p0;
            """,
            """
                p0 := CRobT(\Tool:=tool0 \WObj:=wobj0);
                WZLimSup \Stat, zone, never;
                WZSphDef \Inside, ball, p0.trans, 30;
                WZLimSup \Temp, zone, ball;
                WZLimSup \Stat, zone, ball;
                TPWrite "end";
            """);

        // An undefined shape, \Temp for a wzstationary, and a limit zone the TCP is in: three refusals.
        Assert.Equal(["ERR_ARGVALERR TRUE", "ERR_ARGVALERR TRUE", "ERR_ARGVALERR TRUE", "end"], lines);
    }
}
