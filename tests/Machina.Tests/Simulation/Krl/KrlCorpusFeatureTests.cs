using Machina.Simulation.Krl;

namespace Machina.Tests.Simulation.Krl;

/// <summary>
/// What published KRL programs needed that the twin refused (issue 43, the corpus in docs/simulation.md): GOTO and labels, an
/// argument left out of a call, a CHAR array given its text in a data list, structure components named like keywords, a CHAR
/// given a character code, and clear refusals of CREAD and RSI.
/// </summary>
public class KrlCorpusFeatureTests
{
    private static object Data(KrlTwinController twin, string module, string name) => twin.Modules[module].Data[name].Value;

    [Fact]
    public void MachineDataList_BesideTheProgram_IsSetAside_AndTheProgramRuns()
    {
        // A folder that ships the controller's $custom.dat (as ros-industrial's motion_eki does): its CHANNEL lines and system types
        // (SER, PRO_IO_T, AXIS_OF_COORDINATES) configure the controller, not the program; the twin keeps its own and says so.
        const string machineData = """
            &ACCESS RV$
            &PARAM DISKPATH = MADA
            DEFDAT  $CUSTOM PUBLIC
            BOOL $SR_VEL_RED=TRUE
            DECL AXIS_OF_COORDINATES $TOOL_DIRECTION=#X
            DECL PRO_IO_T $PRO_I_O_SYS={MODULE[] "/R1/CELL()",COLD_BOOT_RUN #ON}
            DECL SER $PSER_1={PROTO 1,PROC 0,RCO 5,BAUD 19200}
            CHANNEL :SER_1 :SER_1 $PSER_1
            ENDDAT
            """;
        using var twin = new KrlTwinController();
        twin.Load(("cell.src", "DEF cell( )\n  PTP {AXIS: A1 15, A2 -90, A3 90, A4 0, A5 90, A6 0}\nEND\n"), ("$custom.dat", machineData));

        Assert.Equal(KrlProgramState.Finished, twin.Run());
        Assert.Equal(15, twin.Arm.Joints.J1, 9);
        Assert.Contains("$custom.dat: $CUSTOM is the controller's machine data (its Mada folder), not a program module: the twin keeps its own and does not load it", twin.Pendant.Lines);
        Assert.DoesNotContain("$custom", twin.Modules.Keys, StringComparer.OrdinalIgnoreCase);
    }

    [Fact]
    public void SubmitProgram_WithItsOwnLoop_RunsOneTurnPerCycle()
    {
        // sps.sub loops on its own (LOOP … ENDLOOP with the user's PLC calls): the submit interpreter runs a turn per 12 ms cycle
        // instead of spinning a processor.
        using var twin = new KrlTwinController();
        twin.Load(("cell.src", "DEF cell( )\nEND\n"), ("sps.sub", "DEF sps( )\n  LOOP\n    turns = turns + 1\n  ENDLOOP\nEND\n"), ("sps.dat", "DEFDAT sps\n  INT turns = 0\nENDDAT\n"));
        using var stop = new CancellationTokenSource(TimeSpan.FromMilliseconds(150));
        var clock = System.Diagnostics.Stopwatch.StartNew();

        twin.RunSubmit("sps", TimeSpan.FromMilliseconds(12), stop.Token);
        double elapsed = clock.Elapsed.TotalMilliseconds;

        int turns = (int)Data(twin, "sps", "turns");
        Assert.InRange(turns, 1, (int)(elapsed / 12) + 2);
    }

    [Fact]
    public void EkiCheck_ShowsTheErrorOfAnEkiFunction_AndStopsTheProgramOnAnAcknowledgementMessage()
    {
        // As published EKI servers check each call: EKI_CHECK(RET, #QUIT) after EKI_Open (Msg_No 0: nothing), a #NOTIFY of a
        // second EKI_Init (23), then #QUIT with the channel named.
        const string program = """
            DEF checked( )
              DECL EKI_STATUS RET
              RET = EKI_Init("Checked")
              EKI_CHECK(RET, #QUIT)
              RET = EKI_Init("Checked")
              EKI_CHECK(RET, #NOTIFY)
              $OUT[3] = TRUE
              EKI_CHECK(RET, #QUIT, "Checked")
              $OUT[4] = TRUE
            END
            """;
        using var twin = new KrlTwinController();
        twin.AddEkiConfiguration("Checked", "<ETHERNETKRL><CONFIGURATION><EXTERNAL><TYPE>Client</TYPE></EXTERNAL><INTERNAL><PORT>0</PORT></INTERNAL></CONFIGURATION></ETHERNETKRL>");
        twin.Load(("checked.src", program));

        KrlProgramState state = twin.Run();

        Assert.Equal(KrlProgramState.Failed, state);
        Assert.Equal("EthernetKRL (Checked): EKI00023: Initialization already performed (EKI_CHECK with #QUIT: an acknowledgement message, which stops the program on the twin) (checked.src, line 8)", twin.Error);
        Assert.Equal("EthernetKRL: EKI00023: Initialization already performed", twin.Pendant.Lines[0]);
        Assert.Contains(twin.Arm.Trace, e => e.Text == "$OUT[3] = TRUE");
        Assert.DoesNotContain(twin.Arm.Trace, e => e.Text == "$OUT[4] = TRUE");
    }

    [Fact]
    public void EkiClearBuffer_OfAnElementTheChannelDoesNotReceive_ClearsNothing_AndTheProgramGoesOn()
    {
        // Machina.NET's original driver (run on KR C4 controllers) clears its SEND element R after each acknowledgement.
        const string program = """
            DEF acks( )
              DECL EKI_STATUS RET
              RET = EKI_Init("Acks")
              RET = EKI_ClearBuffer("Acks", "R")
              RET = EKI_ClearBuffer("Acks", "R")
              $OUT[2] = RET.Msg_No == 0
            END
            """;
        using var twin = new KrlTwinController();
        twin.AddEkiConfiguration("Acks", "<ETHERNETKRL><CONFIGURATION><EXTERNAL><TYPE>Client</TYPE></EXTERNAL><INTERNAL><PORT>0</PORT></INTERNAL></CONFIGURATION><RECEIVE><XML><ELEMENT Tag=\"Cmd/@A\" Type=\"INT\" /></XML></RECEIVE><SEND><XML><ELEMENT Tag=\"R/@ID\" /></XML></SEND></ETHERNETKRL>");
        twin.Load(("acks.src", program));

        KrlProgramState state = twin.Run();

        Assert.True(state == KrlProgramState.Finished, $"{state}: {twin.Error}");
        Assert.Equal(["EthernetKRL Acks: EKI_ClearBuffer of R, which the channel does not receive: nothing cleared (noted once)"], twin.Pendant.Lines);
        Assert.Contains(twin.Arm.Trace, e => e.Text == "$OUT[2] = TRUE");
    }

    [Fact]
    public void Goto_JumpsBack_AndOutOfALoop_ToALabelOfTheRoutine()
    {
        const string source = """
            DEF jumps( )
              INT i
              i = 0
            again:
              i = i + 1
              IF i < 3 THEN
                GOTO again
              ENDIF
              LOOP
                count = count + 1
                IF count >= 5 THEN
                  GOTO done
                ENDIF
              ENDLOOP
              count = -1
            done:
              total = i * 100 + count
            END
            """;
        using var twin = new KrlTwinController();
        twin.Load(("jumps.src", source), ("jumps.dat", "DEFDAT jumps\n  INT count = 0\n  INT total = 0\nENDDAT\n"));

        KrlProgramState state = twin.Run();

        Assert.True(state == KrlProgramState.Finished, $"{state}: {twin.Error}");
        Assert.Equal(305, (int)Data(twin, "jumps", "total"));
    }

    [Fact]
    public void Goto_ToALabelTheRoutineLacks_IsRefusedAtLoad()
    {
        using var twin = new KrlTwinController();
        KrlLoadException ex = Assert.Throws<KrlLoadException>(() => twin.Load(("prog.src", "DEF prog( )\n  GOTO nowhere\nEND\n")));

        Assert.Equal(2, ex.Line);
        Assert.Contains("GOTO nowhere: the routine prog has no label nowhere:", ex.Message, StringComparison.Ordinal);
    }

    [Fact]
    public void Goto_IntoABlockFromOutside_StopsTheProgram()
    {
        using var twin = new KrlTwinController();
        twin.Load(("prog.src", "DEF prog( )\n  GOTO inside\n  IF TRUE THEN\n  inside:\n    $OUT[1] = TRUE\n  ENDIF\nEND\n"));

        Assert.Equal(KrlProgramState.Failed, twin.Run());
        Assert.Equal("GOTO inside: a jump into a control structure (IF, loop, SWITCH) from outside it is not allowed (prog.src, line 2)", twin.Error);
    }

    [Fact]
    public void ArgumentLeftOut_TheOthersArePassed()
    {
        const string source = """
            DEF omit( )
              show(1, , 3)
            END

            DEF show(a :IN, b :IN, c :IN)
              INT a, b, c
              got = a * 10 + c
            END
            """;
        using var twin = new KrlTwinController();
        twin.Load(("omit.src", source), ("omit.dat", "DEFDAT omit\n  INT got = 0\nENDDAT\n"));

        KrlProgramState state = twin.Run();

        Assert.True(state == KrlProgramState.Finished, $"{state}: {twin.Error}");
        Assert.Equal(13, (int)Data(twin, "omit", "got"));
    }

    [Fact]
    public void ArgumentLeftOut_OfASystemFunction_ThatNeedsIt_IsRefusedAtLoad()
    {
        using var twin = new KrlTwinController();
        KrlLoadException ex = Assert.Throws<KrlLoadException>(() => twin.Load(("prog.src", "DEF prog( )\n  REAL r\n  r = ATAN2( , 1)\nEND\n")));

        Assert.Contains("argument 1 of ATAN2 cannot be left out on the twin", ex.Message, StringComparison.Ordinal);
    }

    [Fact]
    public void DataList_CharArrayGivenItsText_HasIt()
    {
        using var twin = new KrlTwinController();
        twin.Load(("names.src", "DEF names( )\nEND\n"), ("names.dat", "DEFDAT names PUBLIC\n  CONST CHAR LABEL_NAME[16]\n  LABEL_NAME[] = \"AxisCorr_1\"\nENDDAT\n"));

        Assert.Equal("AxisCorr_1", KrlValues.Text((KrlArrayValue)Data(twin, "names", "LABEL_NAME")));
    }

    [Fact]
    public void StructComponentsNamedLikeKeywords_AreReadAndWritten()
    {
        const string data = """
            DEFDAT keys
              STRUC cmd_t INT id, step, type
              DECL cmd_t c = {id 1, step 2, type 3}
              INT got = 0
            ENDDAT
            """;
        using var twin = new KrlTwinController();
        twin.Load(("keys.src", "DEF keys( )\n  c.step = c.step + 5\n  got = c.id * 100 + c.step * 10 + c.type\nEND\n"), ("keys.dat", data));

        KrlProgramState state = twin.Run();

        Assert.True(state == KrlProgramState.Finished, $"{state}: {twin.Error}");
        Assert.Equal(173, (int)Data(twin, "keys", "got"));
    }

    [Fact]
    public void CharGivenACharacterCode_HoldsThatCharacter()
    {
        using var twin = new KrlTwinController();
        twin.Load(("eol.src", "DEF eol( )\n  line[1] = 13\n  line[2] = 10\nEND\n"), ("eol.dat", "DEFDAT eol\n  DECL CHAR line[2]\nENDDAT\n"));

        KrlProgramState state = twin.Run();

        Assert.True(state == KrlProgramState.Finished, $"{state}: {twin.Error}");
        Assert.Equal(new object[] { '\r', '\n' }, ((KrlArrayValue)Data(twin, "eol", "line")).ToObjects());
    }

    [Fact]
    public void CharGivenACodeAbove255_StopsTheProgram()
    {
        using var twin = new KrlTwinController();
        twin.Load(("prog.src", "DEF prog( )\n  CHAR c\n  c = 300\nEND\n"));

        Assert.Equal(KrlProgramState.Failed, twin.Run());
        Assert.Equal("Value assignment inadmissible: a CHAR takes a character code from 0 to 255, not 300 (prog.src, line 3)", twin.Error);
    }

    [Fact]
    public void StepNamesAVariable_AndStillStepsAFor()
    {
        const string source = """
            DEF stepper( )
              INT i, count
              count = 0
              FOR i = 1 TO 5 STEP 2
                count = count + 1
              ENDFOR
              got = twice(4) * 10 + count
            END

            DEFFCT INT twice(step :IN)
              INT step
              RETURN step * 2
            ENDFCT
            """;
        using var twin = new KrlTwinController();
        twin.Load(("stepper.src", source), ("stepper.dat", "DEFDAT stepper\n  INT got = 0\nENDDAT\n"));

        KrlProgramState state = twin.Run();

        Assert.True(state == KrlProgramState.Finished, $"{state}: {twin.Error}");
        Assert.Equal(83, (int)Data(twin, "stepper", "got"));
    }

    [Fact]
    public void MsgNotify_WithTheNumberLeftOut_NotifiesOnThePendant()
    {
        using var twin = new KrlTwinController();
        twin.Load(("note.src", "DEF note( )\n  MsgNotify(\"Axis %1 ready\", \"INFO\", , \"A1\")\n  MsgNotify(\"Done\", \"ROS\", 7)\nEND\n"));

        KrlProgramState state = twin.Run();

        Assert.True(state == KrlProgramState.Finished, $"{state}: {twin.Error}");
        Assert.Equal(["NOTIFY INFO: Axis A1 ready", "NOTIFY ROS 7: Done"], twin.Pendant.Lines);
    }

    [Fact]
    public void StrAdd_AppendsAndReturnsTheLength_OrZeroWhenItDoesNotFit()
    {
        const string source = "DEF prog( )\n  CHAR s[8]\n  s[] = \"RUN/\"\n  first = StrAdd(s[], \"abc\")\n  second = StrAdd(s[], \"de\")\n  text[] = s[]\nEND\n";
        using var twin = new KrlTwinController();
        twin.Load(("prog.src", source), ("prog.dat", "DEFDAT prog\nDECL INT first=-1\nDECL INT second=-1\nDECL CHAR text[8]\nENDDAT\n"));

        KrlProgramState state = twin.Run();

        Assert.True(state == KrlProgramState.Finished, $"{state}: {twin.Error}");
        Assert.Equal(7, Data(twin, "prog", "first"));
        Assert.Equal(0, Data(twin, "prog", "second")); // 9 characters do not fit 8: unchanged
        Assert.Equal("RUN/abc", KrlValues.Text((KrlArrayValue)Data(twin, "prog", "text")));
    }

    [Fact]
    public void MsgNotifyTextPar_NotifiesWithItsTextParameters()
    {
        using var twin = new KrlTwinController();
        twin.Load(("note.src", "DEF note( )\n  MsgNotifyTextPar(\"%1 sent %2\", \"DEBUG\", 0, \"ROS\", \"start\")\nEND\n"));

        KrlProgramState state = twin.Run();

        Assert.True(state == KrlProgramState.Finished, $"{state}: {twin.Error}");
        Assert.Equal(["NOTIFY DEBUG 0: ROS sent start"], twin.Pendant.Lines);
    }

    [Fact]
    public void AProgramWhoseFirstRoutineIsNotNamedAfterItsFile_LoadsAndRuns()
    {
        // ros_rsi.src of kuka_experimental and kuka_drivers: DEF RSI_AxisCorr( ), selected and run as the file ros_rsi.
        using var twin = new KrlTwinController();
        twin.Load(("ros_rsi.src", "DEF RSI_AxisCorr( )\n  PTP {AXIS: A1 0, A2 -90, A3 90, A4 0, A5 0, A6 0}\n  Helper()\nEND\nDEF Helper( )\n  $OUT[3] = TRUE\nEND\n"));

        KrlProgramState state = twin.Run();

        Assert.True(state == KrlProgramState.Finished, $"{state}: {twin.Error}");
        Assert.Equal("RSI_AxisCorr", twin.MainRoutine);
        Assert.Equal("$OUT[3] = TRUE", twin.Arm.Trace[^1].Text);
    }

    [Theory]
    [InlineData("DEF prog( )\n  INT ret\n  ret = EKI_Load(\"server\")\nEND\n", 3,
        "EKI_LOAD is not supported by the twin: it is EthernetKRL for iiQKA.OS2")]
    [InlineData("DEF prog( )\n  DECL STATE_T state\n  DECL MODUS_T mode\n  INT n\n  CREAD($CMD, state, mode, \"%d\", n)\nEND\n", 5,
        "CREAD is not supported by the twin: it reads the controller's command channel or reads and writes its serial channels")]
    [InlineData("DEF prog( )\n  INT ret\n  ret = RSI_CHECKID(1)\nEND\n", 3,
        "RSI_CHECKID is not supported by the twin: the twin has RSI_CREATE, RSI_ON, RSI_MOVECORR, RSI_OFF, RSI_DELETE, RSI_SETPUBLICPAR and RSI_GETPUBLICPAR of RSI 3 and 4 (and RSI 2")]
    public void ControllerOptionsTheTwinLacks_AreRefusedAtLoad_WithWhy(string source, int line, string why)
    {
        using var twin = new KrlTwinController();
        KrlLoadException ex = Assert.Throws<KrlLoadException>(() => twin.Load(("prog.src", source)));

        Assert.Equal(line, ex.Line);
        Assert.Contains(why, ex.Message, StringComparison.Ordinal);
    }
}
