using Machina.Simulation.Krl;

namespace Machina.Tests.Simulation.Krl;

/// <summary>
/// What KUKA's own EthernetKRL server (kuka-external-control-sdk) reads of the controller (issue 43): the program states
/// ($PRO_STATE1, $PRO_STATE0 of type PRO_STATE), the millisecond clock ($ROB_TIMER), the drives, safety and mode flags and
/// the path acceleration maxima ($ACC_MA); its CWRITE($CMD, …) loads and stops the program with why when it runs.
/// </summary>
public class KrlProgramManagementTests
{
    private static object Data(KrlTwinController twin, string name) => twin.Modules["prog"].Data[name].Value;

    private const string DataList = """
        DEFDAT prog
        DECL BOOL active=FALSE
        DECL BOOL submit_free=FALSE
        DECL INT waited=0
        DECL REAL acc_ma=0.0
        DECL BOOL drives_off=FALSE
        DECL BOOL mode_t1=FALSE
        DECL INT axes=0
        DECL CHAR name[32]
        DECL STATE_T state
        DECL MODUS_T mode=#SYNC
        ENDDAT
        """;

    [Fact]
    public void StatusVariables_ReadAsTheControllerReportsThem()
    {
        const string source = """
            DEF prog( )
              DECL PRO_STATE robot
              INT start
              robot = $PRO_STATE1
              active = robot == #P_ACTIVE
              submit_free = $PRO_STATE0 == #P_FREE
              start = $ROB_TIMER
              WAIT SEC 0.5
              waited = $ROB_TIMER - start
              acc_ma = $ACC_MA.CP
              $DRIVES_ENABLE = FALSE
              drives_off = NOT $PERI_RDY AND NOT $COULD_START_MOTION AND $ALARM_STOP AND $USER_SAF AND NOT $PRO_MOVE AND $PRO_ACT
              mode_t1 = $T1 AND NOT $T2 AND NOT $AUT AND NOT $EXT
              axes = $NUM_AX * 10 + $EX_AX_NUM
              name[] = $PRO_NAME1[]
            END
            """;
        using var twin = new KrlTwinController();
        Assert.Equal("P_FREE", twin.RobotProgramState);
        twin.Load(("prog.src", source), ("prog.dat", DataList));
        Assert.Equal("P_RESET", twin.RobotProgramState);

        KrlProgramState state = twin.Run();

        Assert.True(state == KrlProgramState.Finished, $"{state}: {twin.Error}");
        Assert.Equal("P_END", twin.RobotProgramState);
        Assert.Equal(true, Data(twin, "active"));
        Assert.Equal(true, Data(twin, "submit_free"));
        Assert.Equal(500, Data(twin, "waited")); // program time outside real time
        Assert.Equal(2.3, (double)Data(twin, "acc_ma"), 9);
        Assert.Equal(true, Data(twin, "drives_off"));
        Assert.Equal(true, Data(twin, "mode_t1"));
        Assert.Equal(60, Data(twin, "axes"));
        Assert.Equal("PROG", KrlValues.Text((KrlArrayValue)Data(twin, "name")).TrimEnd('\0'));
    }

    [Fact]
    public void Cwrite_Run_WhileTheRobotProgramRuns_AnswersAbort_AndAnUnknownCommandStopsTheProgramWithWhy()
    {
        // A RUN needs the robot interpreter free (#P_FREE); the program that writes it runs there, so the controller refuses it.
        const string source = "DEF prog( )\n  active = TRUE\n  CWRITE($CMD, state, mode, \"RUN /R1/other()\")\n  submit_free = state.RET1 == #CMD_ABORT\n  CWRITE($CMD, state, mode, \"DIRLOAD /R1/other()\")\n  active = FALSE\nEND\n";
        using var twin = new KrlTwinController();
        twin.Load(("prog.src", source), ("prog.dat", DataList));

        KrlProgramState state = twin.Run();

        Assert.Equal(KrlProgramState.Failed, state);
        Assert.Equal(true, Data(twin, "submit_free"));
        Assert.Contains("CWRITE($CMD, …, \"RUN /R1/other()\") refused: the robot interpreter's program is #P_ACTIVE", twin.Pendant.Lines);
        Assert.Equal(
            "CWRITE($CMD, …, \"DIRLOAD /R1/other()\") is not supported by the twin: of the program management commands it knows RUN, STOP, RESET and CANCEL (prog.src, line 5)",
            twin.Error);
        Assert.Equal(true, Data(twin, "active"));
        Assert.Equal("P_STOP", twin.RobotProgramState);
    }
}
