using Machina.Simulation.Rapid;

namespace Machina.Tests.Simulation.Rapid;

/// <summary>
/// The YuMi SmartGripper's Hand_… instructions, in a program of our own written the way YuMi socket servers drive the gripper: a
/// grip before calibration raises ERR_HAND_NOTCALIBRATED, which the handler answers by calibrating and retrying; the fingers then
/// travel at the maximum speed to where each instruction sends them, and a value beyond the gripper's range is ERR_ARGVALERR.
/// </summary>
public class RapidSmartGripperTests
{
    private const string Program = """
        MODULE T
          PROC main()
            Hand_GripOutward \holdForce:=15 \targetPos:=20;
            TPWrite "out " + NumToStr(Hand_GetActualPos(), 1) + " mm, " + NumToStr(Hand_GetActualForce(), 1) + " N";
            Hand_MoveTo 10;
            TPWrite "moved " \Num:=Hand_GetActualPos();
            Hand_GripInward;
            TPWrite "in " \Num:=Hand_GetActualPos();
            Hand_SetMaxSpeed 30;
            TPWrite "not reached";
          ERROR
            IF ERRNO = ERR_HAND_NOTCALIBRATED THEN
              TPWrite "calibrating";
              Hand_Initialize \Calibrate;
              RETRY;
            ELSEIF ERRNO = ERR_ARGVALERR THEN
              TPWrite "speed refused, calibrated " \Bool:=Hand_IsCalibrated();
              RETURN;
            ENDIF
          ENDPROC
        ENDMODULE
        """;

    [Fact]
    public void AGripBeforeCalibration_IsCalibratedAndRetried_ThenTheFingersTravelAtTheirSpeed()
    {
        var twin = new RapidTwinController();
        twin.Load(("T.mod", Program));

        RapidProgramState state = twin.Run();

        Assert.True(state == RapidProgramState.Finished, twin.Error);
        Assert.Equal(["calibrating", "out 20 mm, 15 N", "moved 10", "in 0", "speed refused, calibrated TRUE"], twin.Pendant.Lines);
        // 20 mm out, 10 mm in and 10 mm in, at the default 20 mm/s.
        Assert.Equal(2, twin.Clock.Seconds, 6);
    }
}
