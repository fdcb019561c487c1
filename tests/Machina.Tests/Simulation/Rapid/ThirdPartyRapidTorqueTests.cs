using Machina.Simulation.Rapid;

namespace Machina.Tests.Simulation.Rapid;

/// <summary>
/// pygofa's GoFa servers (chenhaox/pygofa, RAPID/SERVER.mod and SEC_SERVER.mod, requests 14 and 15) read the axes' torques with
/// <c>GetJointData \MechUnit:=ROB_1, n \Torque:=torque</c> and <c>GetMotorTorque(n)</c>; the twin refused both at load (session 34:
/// "'GetJointData' is not a procedure"). The twin has no dynamics: each axis reads 0 Nm; an axis the arm lacks is ERR_AXIS_PAR.
/// </summary>
public sealed class ThirdPartyRapidTorqueTests
{
    [Fact]
    public void TorqueReads_AsPygofaWritesThem_GiveZeroNm_AndAnAxisTheArmLacksIsAnError()
    {
        var twin = new RapidTwinController();
        twin.Load([("T.mod", """
            MODULE T
              VAR num torque := 99;
              PROC main()
                VAR string addString;
                GetJointData \MechUnit:=ROB_1, 1 \Torque:=torque;
                addString := NumToStr(torque, 4) + " ";
                addString := addString + NumToStr(GetMotorTorque(6), 5) + " ";
                addString := addString + NumToStr(GetMotorTorque(\MecUnit:=ROB_1, 3), 5);
                TPWrite addString;
                torque := GetMotorTorque(7);
                TPWrite "not reached";
              ERROR
                TPWrite "errno " \Num:=ERRNO;
                TPWrite "axis par " \Bool:=ERRNO = ERR_AXIS_PAR;
              ENDPROC
            ENDMODULE
            """)]);

        Assert.Equal(RapidProgramState.Finished, twin.Run());
        Assert.Equal("0 0 0", twin.Pendant.Lines[0]);
        Assert.Equal("axis par TRUE", twin.Pendant.Lines[2]);
        Assert.Equal(3, twin.Pendant.Lines.Count);
    }
}
