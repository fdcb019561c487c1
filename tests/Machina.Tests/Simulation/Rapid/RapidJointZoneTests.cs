using Machina.Simulation.Rapid;

namespace Machina.Tests.Simulation.Rapid;

/// <summary>
/// Joint world zones (WZLimJointDef, WZHomeJointDef), as cell setups limit an axis and signal a home position: a limit zone in joint
/// space refuses a motion that would take an axis out of its range, an axis given as 9E9 is not supervised, and a home zone's output
/// tells whether every supervised axis is within its delta of the middle.
/// </summary>
public class RapidJointZoneTests
{
    private static RapidTwinController Run(string body, out RapidProgramState state)
    {
        var twin = new RapidTwinController(new RapidTwinOptions { Signals = [("DO_1", "signaldo")] });
        twin.Load(("T.mod", $$"""
            MODULE T
              VAR shapedata space;
              VAR shapedata homeSpace;
              VAR wzstationary axisLimit;
              VAR wztemporary atHome;
              CONST jointtarget low := [[-30, -9E9, 9E9, 9E9, 9E9, 9E9], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
              CONST jointtarget high := [[30, 9E9, 9E9, 9E9, 9E9, 9E9], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
              CONST jointtarget middle := [[0, 0, 0, 9E9, 90, 9E9], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
              CONST jointtarget delta := [[2, 2, 2, 9E9, 2, 9E9], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
              PROC main()
            {{body}}
              ENDPROC
            ENDMODULE
            """));
        state = twin.Run();
        return twin;
    }

    [Fact]
    public void AJointLimitZone_RefusesAMoveThatTakesAnAxisOutOfItsRange_NotOneWithinIt()
    {
        RapidTwinController twin = Run("""
                WZLimJointDef \Outside, space, low, high;
                WZLimSup \Stat, axisLimit, space;
                MoveAbsJ [[25, 10, 10, 45, 60, 100], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]], v1000, fine, tool0;
                TPWrite "within: axis 1 at 25, axes 2 to 6 not supervised";
                MoveAbsJ [[35, 0, 0, 0, 90, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]], v1000, fine, tool0;
                TPWrite "not reached";
            """, out RapidProgramState state);

        Assert.Equal(RapidProgramState.Failed, state);
        Assert.Equal(["within: axis 1 at 25, axes 2 to 6 not supervised"], twin.Pendant.Lines.Take(1));
        Assert.DoesNotContain("not reached", twin.Pendant.Lines);
        Assert.StartsWith("Execution error: line 15: World zone: the motion would take the robot's axes into the limit zone activated at line 12 (WZLimSup)", twin.Error);
        Assert.Equal(25, twin.Arm.Joints.J1, 6); // the refused move did not start
    }

    [Fact]
    public void AHomeZone_SetsItsOutputWhileEverySupervisedAxisIsWithinItsDelta()
    {
        RapidTwinController twin = Run("""
                MoveAbsJ [[1, -1, 1.5, 120, 91, -50], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]], v1000, fine, tool0;
                WZHomeJointDef \Inside, homeSpace, middle, delta;
                WZDOSet \Temp, atHome \Inside, homeSpace, DO_1, 1;
                TPWrite "near home " \Num:=DOutput(DO_1);
                MoveAbsJ [[0, 0, 3, 0, 90, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]], v1000, fine, tool0;
                TPWrite "axis 3 beyond its delta " \Num:=DOutput(DO_1);
                MoveAbsJ [[0, 0, 0, 0, 90, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]], v1000, fine, tool0;
                TPWrite "home " \Num:=DOutput(DO_1);
            """, out RapidProgramState state);

        Assert.True(state == RapidProgramState.Finished, twin.Error);
        Assert.Equal(["near home 1", "axis 3 beyond its delta 0", "home 1"], twin.Pendant.Lines);
    }

    [Fact]
    public void AJointZoneWithALowAboveItsHigh_IsAnArgumentError()
    {
        RapidTwinController twin = Run("""
                WZLimJointDef \Outside, space, high, low;
            """, out RapidProgramState state);

        Assert.Equal(RapidProgramState.Failed, state);
        Assert.Contains("WZLimJointDef: each supervised axis needs a LowJointVal below its HighJointVal", twin.Error, StringComparison.Ordinal);
    }
}
