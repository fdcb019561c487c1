using Machina.Simulation.Krl;
using Machina.Simulation.Twin;

namespace Machina.Tests.Simulation.Krl;

/// <summary>The KRL twin's language: what it refuses at load (with file and line) and what it computes when it runs.</summary>
public class KrlLanguageTests
{
    private static KrlTwinController Run(string source, string? data = null, KrlProgramState expected = KrlProgramState.Finished)
    {
        var twin = new KrlTwinController();
        twin.Load(data is null ? [("prog.src", source)] : [("prog.src", source), ("prog.dat", data)]);
        KrlProgramState state = twin.Run();
        Assert.True(expected == state, $"{state}: {twin.Error}");
        return twin;
    }

    private static object Data(KrlTwinController twin, string name) => twin.Modules["prog"].Data[name].Value;

    private static KrlLoadException Refused(string source, string? data = null)
    {
        var twin = new KrlTwinController();
        return Assert.Throws<KrlLoadException>(() => twin.Load(data is null ? [("prog.src", source)] : [("prog.src", source), ("prog.dat", data)]));
    }

    [Fact]
    public void Mod_IsRefusedAtLoad_WithItsFileAndLine()
    {
        KrlLoadException ex = Refused("DEF prog( )\n  DECL INT i\n  i = 1\n  i = i MOD 100 + 1\nEND\n");

        Assert.Equal("prog.src", ex.File);
        Assert.Equal(4, ex.Line);
        Assert.Equal("prog.src, line 4: KRL has no operator MOD: its arithmetic operators are + - * / (INT division with / truncates)", ex.Message);
    }

    [Theory]
    [InlineData("DEF prog( )\n  x = 1\nEND\n", 2, "unknown name x: it is not declared (DECL) in the routine, its data list or a PUBLIC data list")]
    [InlineData("DEF prog( )\n  DECL BOOL b\n\n  b = 1.5\nEND\n", 4, "type mismatch: b = needs a BOOL value, not REAL")]
    [InlineData("DEF prog( )\n  IF TRUE THEN\n    HALT\nEND\n", 4, "ENDIF is missing")]
    [InlineData("DEF prog( )\n  $POS_ACT = $NULLFRAME\nEND\n", 2, "$POS_ACT is write-protected: a program can only read it")]
    [InlineData("DEF prog( )\n  LIN {A1 0}\nEND\n", 2, "LIN moves to a POS, E6POS or FRAME, not E6AXIS")]
    [InlineData("DEF prog( )\n  go( )\nEND\n", 2, "unknown routine go: no DEF or DEFFCT of that name in the loaded files, and not a system function")]
    [InlineData("DEF prog( )\n  DECL INT i\n  i = 1 < 2 AND TRUE\nEND\n", 3, "type mismatch: INT AND BOOL is not defined in KRL")]
    [InlineData("DEF prog( )\n  $VEL.XY = 1\nEND\n", 2, "VEL_STRUC has no component XY")]
    public void Mistakes_AreRefusedAtLoad_WithTheirLine(string source, int line, string reason)
    {
        KrlLoadException ex = Refused(source);

        Assert.Equal(line, ex.Line);
        Assert.Equal(reason, ex.Reason);
    }

    [Fact]
    public void Loops_Switch_Functions_AndTheDataList_ComputeAsKrlDoes()
    {
        const string source = """
            DEF prog( )
              DECL INT i, k
              total = 0
              FOR i = 1 TO 10 STEP 3
                total = total + i
              ENDFOR
              k = 0
              WHILE k < 5
                k = k + 2
              ENDWHILE
              REPEAT
                k = k - 1
              UNTIL k <= 3
              SWITCH k
              CASE 1, 2
                word[] = "low"
              CASE 3
                word[] = "three"
              DEFAULT
                word[] = "other"
              ENDSWITCH
              half = twice(7) / 4
              rounded = 2.5
              priority = 1 + 2 * 3 == 7
              LOOP
                k = k + 1
                IF k > 100 THEN
                  EXIT
                ENDIF
              ENDLOOP
            END

            DEFFCT INT twice(x:IN)
              DECL INT x
              RETURN 2 * x
            ENDFCT
            """;
        const string data = """
            DEFDAT prog
            DECL INT total=-1
            DECL CHAR word[8]
            DECL INT half
            DECL INT rounded
            DECL BOOL priority=FALSE
            ENDDAT
            """;

        KrlTwinController twin = Run(source, data);

        Assert.Equal(22, Data(twin, "total")); // 1 + 4 + 7 + 10
        Assert.Equal("three", KrlValues.Text((KrlArrayValue)Data(twin, "word")));
        Assert.Equal(3, Data(twin, "half")); // INT division truncates: 14 / 4
        Assert.Equal(3, Data(twin, "rounded")); // REAL to INT rounds: 2.5 -> 3
        Assert.Equal(true, Data(twin, "priority"));
    }

    [Fact]
    public void AxisTarget_BeyondASoftwareLimitSwitch_StopsTheProgramBeforeTheMotion_WithTheMessage()
    {
        KrlTwinController twin = Run("DEF prog( )\n  PTP $AXIS_ACT\n  PTP {AXIS: A1 10, A2 -90, A3 90, A4 0, A5 90, A6 0}\n  PTP {AXIS: A1 175, A2 -90, A3 90, A4 0, A5 90, A6 0}\n  $OUT[3] = TRUE\nEND\n",
            expected: KrlProgramState.Failed);

        Assert.Equal("Software limit switch A1 +: the target 175 deg is beyond 170 deg (prog.src, line 4)", twin.Error);
        Assert.Equal(10, twin.Arm.Joints.J1, 6);
        Assert.DoesNotContain(twin.Arm.Trace, e => e.Kind == TwinTraceKind.Output);
        Assert.Equal(twin.Error, twin.Pendant.Lines[^1]);
    }

    [Fact]
    public void CartesianTarget_OutOfReach_StopsTheProgram_WithTheMessage()
    {
        KrlTwinController twin = Run("DEF prog( )\n  PTP $AXIS_ACT\n  LIN {E6POS: X 2000, Y 0, Z 400, A 180, B 0, C 180}\nEND\n", expected: KrlProgramState.Failed);

        Assert.Equal("Target not reachable: LIN {X 2000, Y 0, Z 400, A 180, B 0, C 180}: it is outside the robot's workspace (prog.src, line 3)", twin.Error);
    }

    [Fact]
    public void Lin_InBaseWithTool_EndsWithTheTcpAtTheTarget_AndPosActReadsItBack()
    {
        const string source = """
            DEF prog( )
              PTP $AXIS_ACT
              $BASE = {X 100, Y 0, Z 0, A 0, B 0, C 0}
              $TOOL = {X 0, Y 0, Z 50, A 0, B 0, C 0}
              $VEL.CP = 0.1
              LIN {E6POS: X 300, Y 100, Z 300, A 180, B 0, C 180}
              reached = $POS_ACT
            END
            """;

        KrlTwinController twin = Run(source, "DEFDAT prog\nDECL E6POS reached\nENDDAT\n");

        Pose tcp = twin.Arm.Tcp;
        Assert.Equal(400, tcp.Position.X, 3);
        Assert.Equal(100, tcp.Position.Y, 3);
        Assert.Equal(300, tcp.Position.Z, 3);
        var reached = (KrlStructValue)Data(twin, "reached");
        Assert.Equal(300, reached.Number("X"), 3);
        Assert.Equal(100, reached.Number("Y"), 3);
        Assert.Equal(180, Math.Abs(reached.Number("A")), 3);
        Assert.Equal(["PTP (BCO run)", "LIN"], twin.Arm.Trace.Where(e => e.Kind == TwinTraceKind.Motion).Select(e => e.Text));
    }
}
