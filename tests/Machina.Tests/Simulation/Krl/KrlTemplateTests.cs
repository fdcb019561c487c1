using Machina.Simulation.Krl;
using Machina.Simulation.Twin;

namespace Machina.Tests.Simulation.Krl;

/// <summary>
/// Programs as the KUKA editor writes them (issue 43): EXT BAS, BAS(#INITMOV,0), folds, inline forms (PTP XP1 with PDAT_ACT and
/// FDAT_ACT from the .dat), the template data types, and the system variables published programs read.
/// </summary>
public class KrlTemplateTests
{
    private const string TemplateSource = """
        &ACCESS RVP
        &REL 3
        &PARAM TEMPLATE = C:\KRC\Roboter\Template\vorgabe
        DEF tmpl( )
        EXT BAS (BAS_COMMAND :IN,REAL :IN )
        ;FOLD INI;%{PE}
          ;FOLD BASISTECH INI
            GLOBAL INTERRUPT DECL 3 WHEN $STOPMESS==TRUE DO IR_STOPM ( )
            INTERRUPT ON 3
            BAS (#INITMOV,0 )
          ;ENDFOLD (BASISTECH INI)
        ;ENDFOLD (INI)
        TOOL_DATA[2] = {X 0,Y 0,Z 50,A 0,B 0,C 0}

        ;FOLD PTP HOME  Vel= 100 % DEFAULT;%{PE}
          $BWDSTART = FALSE
          PDAT_ACT = PDEFAULT
          FDAT_ACT = {TOOL_NO 0,BASE_NO 0,IPO_FRAME #BASE}
          BAS (#FRAMES)
          BAS (#PTP_DAT)
          $H_POS = XHOME
          PTP XHOME
        ;ENDFOLD

        ;FOLD PTP P1 Vel=50 % PDAT1 Tool[0] Base[0];%{PE}
          ;FOLD Parameters ;%{h}
            ;Params IlfProvider=kukaroboter.basistech.inlineforms.movement.old; Kuka.PointName=P1; Kuka.VelocityPtp=50
          ;ENDFOLD
          $BWDSTART = FALSE
          PDAT_ACT = PPDAT1
          FDAT_ACT = FP1
          BAS (#PTP_PARAMS,50)
          SET_CD_PARAMS (0)
          PTP XP1
        ;ENDFOLD
        axesAtP1 = $AXIS_ACT_MEAS
        velocityAtP1 = $VEL_AXIS[1]

        ;FOLD LIN P2 Vel=0.5 m/s CPDAT2 Tool[2] Base[0];%{PE}
          $BWDSTART = FALSE
          LDAT_ACT = LCPDAT2
          FDAT_ACT = FP2
          BAS (#CP_PARAMS,0.5)
          LIN XP2
        ;ENDFOLD
        END
        """;

    private const string TemplateData = """
        &ACCESS RVP
        &REL 3
        DEFDAT  tmpl
        ;FOLD EXTERNAL DECLARATIONS;%{PE}%MKUKATPBASIS,%CEXT,%VCOMMON,%P
        ;FOLD BASISTECH EXT;%{PE}%MKUKATPBASIS,%CEXT,%VEXT,%P
        EXT  BAS (BAS_COMMAND  :IN,REAL  :IN )
        DECL INT SUCCESS
        ;ENDFOLD (BASISTECH EXT)
        ;ENDFOLD (EXTERNAL DECLARATIONS)
        DECL BASIS_SUGG_T LAST_BASIS={POINT1[] "P2                      ",POINT2[] "P2                      ",CP_PARAMS[] "CPDAT2                  ",PTP_PARAMS[] "PDAT1                   ",CONT[] "                        ",CP_VEL[] "0.5                     ",PTP_VEL[] "50                      ",SYNC_PARAMS[] "SYNCDAT                 ",SPL_NAME[] "S0                      ",A_PARAMS[] "ADAT0                   "}
        DECL E6AXIS XP1={A1 20.0000,A2 -80.0000,A3 100.000,A4 0.0,A5 30.0000,A6 10.0000,E1 0.0,E2 0.0,E3 0.0,E4 0.0,E5 0.0,E6 0.0}
        DECL FDAT FP1={TOOL_NO 0,BASE_NO 0,IPO_FRAME #BASE,POINT2[] " "}
        DECL PDAT PPDAT1={VEL 100.000,ACC 100.000,APO_DIST 100.000,APO_MODE #CDIS}
        DECL E6POS XP2={X 300.000,Y 100.000,Z 300.000,A 180.000,B 0.0,C 180.000,E1 0.0,E2 0.0,E3 0.0,E4 0.0,E5 0.0,E6 0.0}
        DECL FDAT FP2={TOOL_NO 2,BASE_NO 0,IPO_FRAME #BASE,POINT2[] " "}
        DECL LDAT LCPDAT2={VEL 2.00000,ACC 100.000,APO_DIST 100.000,APO_FAC 50.0000,AXIS_VEL 100.000,AXIS_ACC 100.000,ORI_TYP #VAR,CIRC_TYP #BASE,JERK_FAC 50.0000,GEAR_JERK 50.0000,EXAX_IGN 0}
        DECL E6AXIS axesAtP1
        DECL INT velocityAtP1
        ENDDAT
        """;

    [Fact]
    public void TemplateProgram_MovesTheArmWhereItsDataSay()
    {
        using var twin = new KrlTwinController();
        twin.Load(("tmpl.src", TemplateSource), ("tmpl.dat", TemplateData));

        KrlProgramState state = twin.Run();

        Assert.True(state == KrlProgramState.Finished, $"{state}: {twin.Error}");
        var atP1 = (KrlStructValue)twin.Modules["tmpl"].Data["axesAtP1"].Value;
        Assert.Equal([20, -80, 100, 0, 30, 10], new[] { "A1", "A2", "A3", "A4", "A5", "A6" }.Select(a => Math.Round(atP1.Number(a), 6)));
        // BAS(#PTP_PARAMS, 50) with PPDAT1's VEL 100 %: the axes at 50 %.
        Assert.Equal(50, (int)twin.Modules["tmpl"].Data["velocityAtP1"].Value);
        // LIN XP2 with TOOL_NO 2 (Z 50 mm) and BAS(#CP_PARAMS, 0.5): the TCP where XP2 says, at 0.5 m/s.
        Pose tcp = twin.Arm.Tcp;
        Assert.Equal(300, tcp.Position.X, 3);
        Assert.Equal(100, tcp.Position.Y, 3);
        Assert.Equal(300, tcp.Position.Z, 3);
        Assert.Equal(50, ((KrlStructValue)twin.Environment.System["$TOOL"].Value).Number("Z"), 6);
        Assert.Equal(0.5, ((KrlStructValue)twin.Environment.System["$VEL"].Value).Number("CP"), 6);
        Assert.Equal(["PTP (BCO run)", "PTP", "LIN"], twin.Arm.Trace.Where(e => e.Kind == TwinTraceKind.Motion).Select(e => e.Text));
    }

    [Theory]
    [InlineData("prog.src", "DEF prog( )\n  EXT MISSING_ROUTINE (INT :IN)\n  HALT\nEND\n", null, 2, "MISSING_ROUTINE")]
    [InlineData("prog.dat", "DEF prog( )\nEND\n", "DEFDAT prog\nEXTFCT INT other_fct (REAL :IN)\nENDDAT\n", 2, "other_fct")]
    public void ExtOfARoutineThatIsNotThere_IsRefusedAtLoad_WithFileLineAndName(string file, string source, string? data, int line, string name)
    {
        using var twin = new KrlTwinController();
        KrlLoadException ex = Assert.Throws<KrlLoadException>(() =>
            twin.Load(data is null ? [("prog.src", source)] : [("prog.src", source), ("prog.dat", data)]));

        Assert.Equal(file, ex.File);
        Assert.Equal(line, ex.Line);
        Assert.Contains($"EXT {name}: no routine of that name is loaded", ex.Message, StringComparison.Ordinal);
    }

    [Fact]
    public void ExtOfALoadedRoutine_Loads_AndTheCallRuns()
    {
        using var twin = new KrlTwinController();
        twin.Load(("prog.src", "DEF prog( )\n  EXT helper ( )\n  helper( )\nEND\n"), ("helper.src", "DEF helper( )\n  $OUT[7] = TRUE\nEND\n"));

        Assert.Equal(KrlProgramState.Finished, twin.Run("prog"));
        Assert.True((bool)((KrlArrayValue)twin.Environment.System["$OUT"].Value)[6]);
    }

    /// <summary>
    /// Outside real-time mode the timers count program time, and a WAIT FOR looks again every interpreter cycle (12 ms of it) while a
    /// timer runs: the timer passes 0 on the third look after each reset (-30, -18, -6, 6), so three interrupts take nine cycles
    /// and the timer stops at 6 ms, whatever the load of the machine.
    /// </summary>
    [Fact]
    public void TimerFlagInterrupt_FiresEachTimeTheTimerPassesZero()
    {
        const string source = """
            DEF timer( )
              INTERRUPT DECL 16 WHEN $TIMER_FLAG[1]==TRUE DO tick( )
              INTERRUPT ON 16
              $TIMER[1] = -30
              $TIMER_STOP[1] = FALSE
              WAIT FOR $FLAG[3]
              $TIMER_STOP[1] = TRUE
              finalTimer = $TIMER[1]
            END

            DEF tick( )
              ticks = ticks + 1
              IF ticks >= 3 THEN
                $FLAG[3] = TRUE
              ELSE
                $TIMER[1] = -30
              ENDIF
            END
            """;
        using var twin = new KrlTwinController();
        twin.Load(("timer.src", source), ("timer.dat", "DEFDAT timer\n  INT ticks = 0\n  INT finalTimer = -1\nENDDAT\n"));

        KrlProgramState state = twin.Run();

        Assert.True(state == KrlProgramState.Finished, $"{state}: {twin.Error}");
        Assert.Equal(3, (int)twin.Modules["timer"].Data["ticks"].Value);
        Assert.Equal(6, (int)twin.Modules["timer"].Data["finalTimer"].Value);
        Assert.Equal(9 * 0.012, twin.Clock.Seconds, 9);
    }

    [Fact]
    public void MeasuredPose_ModeAndCyclicFlags_ReadAsTheControllerHasThem()
    {
        const string source = """
            DEF meas( )
              PTP {AXIS: A1 15, A2 -85, A3 95, A4 5, A5 25, A6 -5}
              measured = $AXIS_ACT_MEAS
              position = $POS_ACT_MES
              t1 = $MODE_OP == #T1
              $CYCFLAG[4] = TRUE
              cyc = $CYCFLAG[4]
            END
            """;
        using var twin = new KrlTwinController();
        twin.Load(("meas.src", source), ("meas.dat", "DEFDAT meas\n  DECL E6AXIS measured\n  DECL E6POS position\n  BOOL t1 = FALSE\n  BOOL cyc = FALSE\nENDDAT\n"));

        KrlProgramState state = twin.Run();

        Assert.True(state == KrlProgramState.Finished, $"{state}: {twin.Error}");
        var measured = (KrlStructValue)twin.Modules["meas"].Data["measured"].Value;
        Assert.Equal(15, measured.Number("A1"), 6);
        Assert.Equal(-5, measured.Number("A6"), 6);
        var position = (KrlStructValue)twin.Modules["meas"].Data["position"].Value;
        Assert.Equal(twin.Arm.Tcp.Position.X, position.Number("X"), 6);
        Assert.True((bool)twin.Modules["meas"].Data["t1"].Value);
        Assert.True((bool)twin.Modules["meas"].Data["cyc"].Value);
    }

    [Fact]
    public void BasOfACommandTheTwinLacks_StopsTheProgram_WithItsName()
    {
        using var twin = new KrlTwinController();
        twin.Load(("prog.src", "DEF prog( )\n  BAS (#GRIPPER, 1)\nEND\n"));

        Assert.Equal(KrlProgramState.Failed, twin.Run());
        Assert.StartsWith("BAS(#GRIPPER) is not supported by the twin", twin.Error, StringComparison.Ordinal);
        Assert.EndsWith("(prog.src, line 2)", twin.Error, StringComparison.Ordinal);
    }
}
