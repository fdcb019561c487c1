using Machina.Simulation.Rapid;

namespace Machina.Tests.Simulation.Rapid;

/// <summary>
/// CalcJointT's errors as YuMi socket servers handle them: a target beyond the arm's working area raises ERR_OUTSIDE_REACH (not
/// ERR_ROBLIMIT, which is for a target reached only with an axis beyond its limits), and a reachable one gives its joints.
/// </summary>
public class RapidCalcJointTTests
{
    [Fact]
    public void ATargetOutsideTheWorkingArea_RaisesErrOutsideReach_AReachableOneGivesItsJoints()
    {
        var twin = new RapidTwinController();
        twin.Load(("T.mod", """
            MODULE T
              VAR jointtarget j;
              VAR robtarget p;
              PROC main()
                p := CRobT(\Tool:=tool0 \WObj:=wobj0);
                j := CalcJointT(p, tool0);
                TPWrite "here: axis 5 at " \Num:=Round(j.robax.rax_5 \Dec:=3);
                p.trans.x := 3000;
                j := CalcJointT(p, tool0);
                TPWrite "not reached";
              ERROR
                TPWrite "outside reach " \Bool:=ERRNO = ERR_OUTSIDE_REACH;
                TPWrite "robot limit " \Bool:=ERRNO = ERR_ROBLIMIT;
              ENDPROC
            ENDMODULE
            """));

        Assert.Equal(RapidProgramState.Finished, twin.Run());
        Assert.Equal(["here: axis 5 at 90", "outside reach TRUE", "robot limit FALSE"], twin.Pendant.Lines);
    }
}
